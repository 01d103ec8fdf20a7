#!/usr/bin/env bash
# The public API is the only way in: the installed headers, the tools, the
# image files (image/), the renderer, the Python module (python/src) and the
# example programs include nothing of libscene's private folders, and the
# public headers include only each other, glm and the standard library.
# Tests may include private headers (they test them), so *_test.cpp files
# and tests/ are not checked.
#
#   check_public_api.sh SOURCE_DIR
set -euo pipefail
root=${1:?usage: check_public_api.sh SOURCE_DIR}
cd "$root"
failures=0

# Sources that must use the public API only.
mapfile -t users < <(find image tools renderer examples bench python -name '*.cpp' -o -name '*.h' |
  grep -v '_test\.cpp$' | grep -v '^tools/tool_test_support\.h$' | sort)
# bench/read_bench.cpp and bench/render_probe.cpp time one reader or writer
# on its own, below the registry: benchmarks of the internals, by design.
for file in "${users[@]}"; do
  case $file in bench/read_bench.cpp | bench/render_probe.cpp) continue ;; esac
  if grep -nE '#include [<"]libscene/' "$file"; then
    echo "FAIL: $file includes a private libscene header; use <scenefile/...>" >&2
    failures=$((failures + 1))
  fi
done

# The public headers themselves.
while IFS= read -r header; do
  while IFS= read -r line; do
    target=$(sed -E 's/^#include [<"]([^>"]+)[>"].*/\1/' <<<"$line")
    if [[ $target == */* && $target != scenefile/* && $target != glm/* ]]; then
      echo "FAIL: $header includes $target, which is not installed" >&2
      failures=$((failures + 1))
    fi
  done < <(grep -E '^#include ' "$header")
done < <(find include/scenefile -name '*.h' | sort)

if ((failures > 0)); then
  echo "FAIL: $failures includes of private headers" >&2
  exit 1
fi
echo "PASS: ${#users[@]} sources and $(find include/scenefile -name '*.h' | wc -l) public headers use the public API only"
