#!/usr/bin/env bash
# The folders of cosim/ depend on each other in one direction: a file in a folder includes
# (#include "cosim/FOLDER/...") only its own folder and those listed before it in the folder
# table of docs/architecture.md ("| folder | purpose |", rows in dependency order, bottom
# first), so that the table is the one statement of that order. Lists every include that points
# to a later folder, and every folder the table does not list.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
doc="$root/docs/architecture.md"
cd "$root"

# The folder table's rows in order: "| `case/` | ..." after the header "| folder | purpose |".
mapfile -t order < <(awk '
  /^\| folder \| purpose \|/ { inTable = 1; next }
  inTable && /^\|[- |]*\|$/ { next }
  inTable && /^\|/ { if (match($0, /^\| `[a-z_]+\/`/)) print substr($0, 4, RLENGTH - 5); next }
  inTable { exit }' "$doc")
if ((${#order[@]} == 0)); then
  echo "docs/architecture.md: no folder table (| folder | purpose |) found"
  exit 1
fi
declare -A rank
for i in "${!order[@]}"; do rank[${order[$i]}]=$i; done

problems=0
for dir in cosim/*/; do
  folder=$(basename "$dir")
  if [[ -z ${rank[$folder]+set} ]]; then
    echo "cosim/$folder/ is not in the folder table of docs/architecture.md"
    problems=$((problems + 1))
  fi
done

while IFS=: read -r file line text; do
  from=${file#cosim/}
  from=${from%%/*}
  to=${text#*\"cosim/}
  to=${to%%/*}
  [[ $from == "$to" || -z ${rank[$from]+set} ]] && continue
  if [[ -z ${rank[$to]+set} ]]; then
    continue  # reported above as a folder missing from the table
  fi
  if ((rank[$to] > rank[$from])); then
    echo "$file:$line: $from/ includes $to/, which the folder table lists after it"
    problems=$((problems + 1))
  fi
done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]+"cosim/[a-z_]+/' cosim --include='*.hpp' --include='*.cpp' | sort -t: -k1,1 -k2,2n)

if ((problems > 0)); then
  echo "$problems folder-order problem(s): move the include, the file, or the folder's row in docs/architecture.md"
  exit 1
fi
echo "cosim/ folders include only themselves and the folders listed before them (${order[*]})"
