#!/usr/bin/env bash
# The grammars' tests (ctest editors.vscode.grammars):
#
#   bash grammar-tests.sh TESTDATA WORK [--update]
#
# 1. every .sf and .txt file of TESTDATA/valid is tokenised by
#    vscode-tmgrammar-snap and must give exactly the tokens of its snapshot
#    in snapshots/ (a file without one fails); nothing in them is invalid;
# 2. the assertion tests in grammar/ pin keywords, numbers and what is
#    invalid (vscode-tmgrammar-test);
# 3. the manifest's firstLine recognises the valid instruction files.
# --update rewrites snapshots/ from the grammars as they are, after a
# deliberate change. Exits 77 (skipped) when node or node_modules is missing.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
extension=$(dirname "$here")
testdata=${1:?usage: grammar-tests.sh TESTDATA WORK [--update]}
work=${2:?usage: grammar-tests.sh TESTDATA WORK [--update]}
update=${3:-}
bin=$extension/node_modules/.bin
if ! command -v node >/dev/null 2>&1; then
  echo "SKIP: node is not installed (scripts/install-deps.sh installs it)"; exit 77
fi
if [ ! -x "$bin/vscode-tmgrammar-snap" ]; then
  echo "SKIP: editors/vscode/node_modules is missing (scripts/install-deps.sh runs npm ci)"; exit 77
fi
manifest=$extension/package.json

# The snapshots lie beside copies of the files, where the tool looks for them.
rm -rf "$work" && mkdir -p "$work"
cp "$testdata"/valid/*.sf "$testdata"/valid/*.txt "$work/"
failures=0
if [ "$update" = --update ]; then
  rm -f "$here"/snapshots/*.snap
else
  for file in "$work"/*.sf "$work"/*.txt; do
    name=$(basename "$file")
    if [ -e "$here/snapshots/$name.snap" ]; then
      cp "$here/snapshots/$name.snap" "$work/"
    else
      echo "FAIL: no snapshot for $name: run $0 $testdata $work --update" >&2
      failures=$((failures + 1))
    fi
  done
  for snap in "$here"/snapshots/*.snap; do
    [ -e "$testdata/valid/$(basename "$snap" .snap)" ] ||
      { echo "FAIL: $(basename "$snap") has no file in $testdata/valid" >&2; failures=$((failures + 1)); }
  done
fi
# Instruction files say nothing by their extension: each kind is named.
"$bin/vscode-tmgrammar-snap" --config "$manifest" -s source.scenefile "$work/*.sf" ||
  failures=$((failures + 1))
"$bin/vscode-tmgrammar-snap" --config "$manifest" -s source.scenefile-instructions "$work/*.txt" ||
  failures=$((failures + 1))
if [ "$update" = --update ]; then
  mkdir -p "$here/snapshots"
  cp "$work"/*.snap "$here/snapshots/"
fi
if grep -l 'invalid\.' "$work"/*.snap >&2; then
  echo "FAIL: the grammars mark something invalid in the valid files above" >&2
  failures=$((failures + 1))
fi

(cd "$here/grammar" && "$bin/vscode-tmgrammar-test" --config "$manifest" '*') ||
  failures=$((failures + 1))

# VS Code tells an instruction file by its first line (the manifest's
# firstLine): every valid one whose first line is not blank, and no scene file.
node - "$manifest" "$testdata"/valid/*.sf "$testdata"/valid/*.txt <<'SCRIPT' || failures=$((failures + 1))
const fs = require('fs');
const [manifest, ...files] = process.argv.slice(2);
const language = JSON.parse(fs.readFileSync(manifest, 'utf8')).contributes.languages
  .find((l) => l.id === 'scenefile-instructions');
const firstLine = new RegExp(language.firstLine);
let wrong = 0;
for (const file of files) {
  const line = fs.readFileSync(file, 'utf8').split(/\r?\n/)[0];
  const expected = file.endsWith('.txt') && line.trim() !== '';
  if (firstLine.test(line) !== expected) {
    console.error(`FAIL: firstLine ${expected ? 'misses' : 'takes'} ${file}`);
    wrong++;
  }
}
process.exit(wrong === 0 ? 0 : 1);
SCRIPT
if [ "$failures" -ne 0 ]; then
  echo "FAIL: $failures of the grammar checks failed" >&2
  exit 1
fi
echo "the grammars give the snapshots of every valid file and pass the assertion tests; firstLine tells the instruction files"
