#!/usr/bin/env bash
# Every module a script in scripts/ imports is in Python's standard library, is another script of
# scripts/, or comes with a Debian package that scripts/install_deps.sh --with-python installs,
# and every shell script that runs /usr/bin/python3 calls install_deps.sh with --with-python
# first (run by ctest).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root/scripts"
# The Debian package of each third-party module the scripts may import.
declare -A debian=([numpy]=python3-numpy [matplotlib]=python3-matplotlib [vtk]=python3-vtk9
                   [vtkmodules]=python3-vtk9)
stdlib=" argparse csv math os sys json pathlib re subprocess collections itertools functools typing dataclasses "
packages=$(sed -n 's/^PYTHON_PACKAGES=(\(.*\))/\1/p' install_deps.sh)
status=0
declare -A needs  # scripts that import a third-party module
check_imports() {  # file: its import lines (a .py file, or the inline Python of a shell script)
  local file=$1 mod pkg
  for mod in $(sed -nE 's/^[[:space:]]*(import|from)[[:space:]]+([A-Za-z_][A-Za-z0-9_]*).*/\2/p' "$file" | sort -u); do
    [[ "$stdlib" == *" $mod "* ]] && continue
    [[ -f "$mod.py" ]] && continue  # another script of scripts/ (its own imports are checked)
    needs[$file]=1
    pkg="${debian[$mod]:-}"
    if [[ -z "$pkg" ]]; then
      echo "check_python_deps: scripts/$file imports '$mod', which is neither in the standard-library list nor mapped to a Debian package here"
      status=1
    elif [[ " $packages " != *" $pkg "* ]]; then
      echo "check_python_deps: scripts/$file imports '$mod' (Debian $pkg), which install_deps.sh --with-python does not install"
      status=1
    fi
  done
}
for f in *.py *.sh; do check_imports "$f"; done
for sh in *.sh; do
  [[ "$sh" == check_python_deps.sh || "$sh" == install_deps.sh ]] && continue
  uses=${needs[$sh]:-}
  for py in $(grep -oE '[A-Za-z_]+\.py' "$sh" | sort -u); do [[ -n "${needs[$py]:-}" ]] && uses=1; done
  if [[ -n "$uses" ]] && ! grep -q 'install_deps.sh" --with-python' "$sh"; then
    echo "check_python_deps: scripts/$sh runs Python that needs Debian's python3 packages but does not call install_deps.sh --with-python"
    status=1
  fi
done
[[ $status -eq 0 ]] && echo "check_python_deps: ok"
exit $status
