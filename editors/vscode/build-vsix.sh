#!/usr/bin/env bash
# Compiles the extension and packages it to a .vsix, outside the source tree:
#
#   bash build-vsix.sh STAGE VERSION OUTPUT.vsix
#
# STAGE receives what the package holds: the manifest with its version set
# to VERSION (the project's), the compiled out/extension.js, the grammars,
# the language configurations, the README, and a link to this folder's
# node_modules, from which vsce copies the runtime dependencies
# (vscode-languageclient). Nothing here uses the network.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
stage=${1:?usage: build-vsix.sh STAGE VERSION OUTPUT.vsix}
version=${2:?usage: build-vsix.sh STAGE VERSION OUTPUT.vsix}
output=${3:?usage: build-vsix.sh STAGE VERSION OUTPUT.vsix}
if [ ! -x "$here/node_modules/.bin/vsce" ] || [ ! -x "$here/node_modules/.bin/tsc" ]; then
  echo "build-vsix: $here/node_modules is missing: run npm ci there (scripts/install-deps.sh does)" >&2
  exit 1
fi
rm -rf "$stage"
mkdir -p "$stage" "$(dirname "$output")"
"$here/node_modules/.bin/tsc" -p "$here" --outDir "$stage/out"
cp -R "$here/syntaxes" "$here/language-configuration" "$here/README.md" "$here/.vscodeignore" \
  "$stage/"
node -e '
  const fs = require("fs");
  const [source, target, version] = process.argv.slice(1);
  const manifest = JSON.parse(fs.readFileSync(source, "utf8"));
  manifest.version = version;
  fs.writeFileSync(target, JSON.stringify(manifest, null, 2) + "\n");
' "$here/package.json" "$stage/package.json" "$version"
ln -s "$here/node_modules" "$stage/node_modules"
# No licence file and no repository: the project has neither, and vsce
# would otherwise stop to ask.
# vsce lists every file it packs: kept in STAGE.log, shown on failure.
if ! (cd "$stage" && "$here/node_modules/.bin/vsce" package --skip-license \
        --allow-missing-repository --out "$output") >"$stage.log" 2>&1; then
  cat "$stage.log" >&2
  exit 1
fi
