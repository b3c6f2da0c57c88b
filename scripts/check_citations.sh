#!/usr/bin/env bash
# Code, docs, scripts and examples cite docs/ sections or published literature only: no
# project-internal issue numbers and no documents outside the repository (run by ctest).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
pattern='GUIDE|\.\./shared|[Ii]ssue #?[0-9]'
hits=$(grep -rnIE "$pattern" cosim lube fem modal acoustics tests scripts bench examples meshes cmake docs \
         README.md CMakeLists.txt --exclude=check_citations.sh || true)
if [[ -n "$hits" ]]; then
  echo "check_citations: these lines cite an issue number or a document outside the repository;"
  echo "cite a docs/ section or the published source instead:"
  echo "$hits"
  exit 1
fi
echo "check_citations: ok"
