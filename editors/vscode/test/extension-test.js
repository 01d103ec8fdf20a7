// The extension's own logic, in node with stand-ins for VS Code and the
// language client (ctest editors.vscode.extension):
//
//   node extension-test.js OUT/extension.js
//
// Exits 77 (skipped) when the extension was not compiled.
// It starts sfls as the settings say, for both languages, under the id that
// reads scenefile.trace.server; and scenefile.render, run from the palette,
// sends the active document's URI and the render settings, shows the image
// written, shows the server's reason when it fails, and passes arguments
// that a caller gave through untouched.
'use strict';
const assert = require('assert');
const Module = require('module');
const extensionFile = process.argv[2];
if (!require('fs').existsSync(extensionFile)) {
  console.log(`SKIP: ${extensionFile} was not built (no editors/vscode/node_modules: scripts/install-deps.sh)`);
  process.exit(77);
}

const shown = { info: [], error: [], opened: [] };
class CancellationError extends Error {}
const vscode = {
  CancellationError,
  Uri: { file: (path) => ({ path }) },
  workspace: {
    getConfiguration: (section) => ({
      get: (key) => ({ 'server.path': '/opt/sf/bin/sfls', 'render.arguments': { width: 64 } })[key],
      section,
    }),
    onDidChangeConfiguration: () => ({ dispose() {} }),
  },
  window: {
    activeTextEditor: { document: { uri: { toString: () => 'file:///w/a.sf' }, languageId: 'scenefile' } },
    showInformationMessage: async (message, ...items) => (shown.info.push(message), items[0]),
    showErrorMessage: async (message) => void shown.error.push(message),
  },
  commands: { executeCommand: async (command, uri) => void shown.opened.push([command, uri.path]) },
};
const clients = [];
const languageClient = {
  TransportKind: { stdio: 0 },
  LanguageClient: class {
    constructor(id, name, serverOptions, clientOptions) {
      clients.push({ id, name, serverOptions, clientOptions });
    }
    async start() {}
    async stop() {}
  },
};
const stubs = { vscode, 'vscode-languageclient/node': languageClient };
const load = Module._load;
Module._load = function (request, ...rest) {
  return request in stubs ? stubs[request] : load.call(this, request, ...rest);
};

(async () => {
  const extension = require(extensionFile);
  await extension.activate({ subscriptions: [] });
  assert.strictEqual(clients.length, 1);
  const [client] = clients;
  assert.strictEqual(client.id, 'scenefile');
  assert.strictEqual(client.serverOptions.command, '/opt/sf/bin/sfls');
  const languages = client.clientOptions.documentSelector.map((s) => s.language);
  assert.deepStrictEqual([...new Set(languages)].sort(), ['scenefile', 'scenefile-instructions']);

  const executeCommand = client.clientOptions.middleware.executeCommand;
  const sent = [];
  const answer = (result) => async (command, args) => (sent.push([command, args]), result);
  await executeCommand('scenefile.render', [], answer({ image: '/w/a.png' }));
  assert.deepStrictEqual(sent.pop(), ['scenefile.render', ['file:///w/a.sf', { width: 64 }]]);
  assert.deepStrictEqual(shown.info, ['Rendered /w/a.png']);
  assert.deepStrictEqual(shown.opened, [['vscode.open', '/w/a.png']]);

  const given = ['file:///w/b.txt', { spp: 4 }];
  await executeCommand('scenefile.render', given, answer({ image: '/w/b.png' }));
  assert.deepStrictEqual(sent.pop(), ['scenefile.render', given]);

  const fail = async () => { throw new Error('width must be at least 1'); };
  await executeCommand('scenefile.render', [], fail);
  assert.deepStrictEqual(shown.error, ['Render: width must be at least 1']);
  const cancel = async () => { throw new CancellationError(); };
  await executeCommand('scenefile.render', [], cancel);
  assert.strictEqual(shown.error.length, 1);

  vscode.window.activeTextEditor = undefined;
  await executeCommand('scenefile.render', [], answer(undefined));
  assert.strictEqual(sent.length, 0);
  assert.match(shown.error[1], /open a scene file or an instruction file/);
  await extension.deactivate();
  console.log('the extension starts sfls as set and renders the active document');
})().catch((error) => {
  console.error(error);
  process.exit(1);
});
