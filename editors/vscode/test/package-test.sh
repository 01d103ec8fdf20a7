#!/usr/bin/env bash
# The .vsix as VS Code gets it (ctest editors.vscode.package):
#
#   bash package-test.sh EXTENSION.vsix VERSION WORK
#
# It lists the compiled extension, both grammars, both language
# configurations, the manifest and the client library; its manifest has the
# project's version, the two languages, the grammars and scenefile.render;
# and out/extension.js, unpacked, loads with every module it needs from the
# package itself (a stand-in for VS Code's own module "vscode").
# Exits 77 (skipped) when the build could not make the .vsix (no node or
# no editors/vscode/node_modules).
set -euo pipefail
vsix=${1:?usage: package-test.sh EXTENSION.vsix VERSION WORK}
version=${2:?usage: package-test.sh EXTENSION.vsix VERSION WORK}
work=${3:?usage: package-test.sh EXTENSION.vsix VERSION WORK}
if [ ! -e "$vsix" ]; then
  if ! command -v node >/dev/null 2>&1 || [ ! -d "$(dirname "$0")/../node_modules" ]; then
    echo "SKIP: no node or editors/vscode/node_modules, so no .vsix (scripts/install-deps.sh)"
    exit 77
  fi
  echo "FAIL: $vsix was not built (configure again after npm ci, then build vscode-extension)" >&2
  exit 1
fi
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

listing=$(unzip -l "$vsix")
for file in extension/out/extension.js extension/package.json extension/README.md \
            extension/syntaxes/scenefile.tmLanguage.json \
            extension/syntaxes/instructions.tmLanguage.json \
            extension/language-configuration/scenefile.json \
            extension/language-configuration/instructions.json \
            extension/node_modules/vscode-languageclient/package.json; do
  grep -q " $file\$" <<<"$listing" || fail "$(basename "$vsix") has no $file"
done
for file in extension/src/extension.ts extension/tsconfig.json extension/package-lock.json; do
  ! grep -q " $file\$" <<<"$listing" || fail "$(basename "$vsix") holds $file"
done
grep -q ' extension/node_modules/\(typescript\|@vscode/vsce\|vscode-tmgrammar-test\)/' <<<"$listing" &&
  fail "$(basename "$vsix") holds a development dependency"

rm -rf "$work" && mkdir -p "$work"
unzip -q "$vsix" -d "$work"
node - "$work/extension" "$version" <<'SCRIPT' || fail "the unpacked extension does not load as packaged"
const path = require('path');
const Module = require('module');
const [folder, version] = process.argv.slice(2);
const manifest = require(path.join(folder, 'package.json'));
const problems = [];
if (manifest.version !== version) problems.push(`version ${manifest.version}, not ${version}`);
const languages = (manifest.contributes.languages || []).map((l) => l.id).sort().join(' ');
if (languages !== 'scenefile scenefile-instructions') problems.push(`languages: ${languages}`);
const scopes = (manifest.contributes.grammars || []).map((g) => g.scopeName).sort().join(' ');
if (scopes !== 'source.scenefile source.scenefile-instructions') problems.push(`grammars: ${scopes}`);
if (!(manifest.contributes.commands || []).some((c) => c.command === 'scenefile.render'))
  problems.push('no command scenefile.render');
// VS Code gives extensions the module "vscode"; everything else must come
// from the package. This test only loads the extension (runs its top
// level), so in place of VS Code's API an object that answers any property
// with an empty constructor will do; the extension's behaviour, against a
// fuller stand-in, is editors.vscode.extension's to test.
const vscodeApi = new Proxy({}, { get: (_, name) => (name === '__esModule' ? false : function () {}) });
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, parent, ...rest) {
  if (request === 'vscode') return 'vscode';
  const found = resolve.call(this, request, parent, ...rest);
  if (!found.startsWith(folder + path.sep) && !Module.isBuiltin(found))
    problems.push(`${request} resolves outside the package: ${found}`);
  return found;
};
require.cache.vscode = { id: 'vscode', filename: 'vscode', loaded: true, exports: vscodeApi };
const extension = require(path.join(folder, manifest.main));
if (typeof extension.activate !== 'function' || typeof extension.deactivate !== 'function')
  problems.push('out/extension.js exports no activate and deactivate');
for (const problem of problems) console.error(`package: ${problem}`);
process.exit(problems.length === 0 ? 0 : 1);
SCRIPT
if [ "$failures" -ne 0 ]; then
  exit 1
fi
echo "$(basename "$vsix"): the extension, its grammars and its client library, loadable as packaged"
