// Starts sfls for scene files and instruction files, and gives its command
// scenefile.render the active document when it is run from the palette.
import * as vscode from 'vscode';
import {
  ExecuteCommandSignature,
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
  TransportKind,
} from 'vscode-languageclient/node';

const renderCommand = 'scenefile.render';
let client: LanguageClient | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (change) => {
      if (change.affectsConfiguration('scenefile.server.path')) {
        await stopClient();
        await startClient();
      }
    }),
  );
  await startClient();
}

export async function deactivate(): Promise<void> {
  await stopClient();
}

async function startClient(): Promise<void> {
  const command = vscode.workspace.getConfiguration('scenefile').get<string>('server.path') || 'sfls';
  const serverOptions: ServerOptions = { command, transport: TransportKind.stdio };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'scenefile' },
      { scheme: 'file', language: 'scenefile-instructions' },
      { scheme: 'untitled', language: 'scenefile' },
      { scheme: 'untitled', language: 'scenefile-instructions' },
    ],
    // The client registers the server's commands itself; this fills in
    // what the palette cannot pass.
    middleware: { executeCommand: executeServerCommand },
  };
  // The id "scenefile" makes the client read the setting scenefile.trace.server.
  client = new LanguageClient('scenefile', 'Scene files', serverOptions, clientOptions);
  await client.start();
}

async function stopClient(): Promise<void> {
  const running = client;
  client = undefined;
  if (running) {
    await running.stop();
  }
}

// scenefile.render takes [document URI, sfrender's settings]; run from the
// palette it has no arguments, and renders the active editor's document with
// the setting scenefile.render.arguments.
async function executeServerCommand(
  command: string,
  args: unknown[],
  next: ExecuteCommandSignature,
): Promise<unknown> {
  if (command !== renderCommand || args.length > 0) {
    return next(command, args);
  }
  const document = vscode.window.activeTextEditor?.document;
  if (!document || !['scenefile', 'scenefile-instructions'].includes(document.languageId)) {
    void vscode.window.showErrorMessage('Render: open a scene file or an instruction file first.');
    return undefined;
  }
  const settings = vscode.workspace.getConfiguration('scenefile').get<object>('render.arguments') ?? {};
  let result: unknown;
  try {
    result = await next(command, [document.uri.toString(), settings]);
  } catch (error) {
    // The client says that the request failed; the server's message says
    // why (an argument, the document's errors, the write). A render the
    // user cancelled needs no message.
    if (!(error instanceof vscode.CancellationError)) {
      const message = error instanceof Error ? error.message : String(error);
      void vscode.window.showErrorMessage(`Render: ${message}`);
    }
    return undefined;
  }
  const image = imagePath(result);
  if (image) {
    const open = await vscode.window.showInformationMessage(`Rendered ${image}`, 'Open');
    if (open) {
      await vscode.commands.executeCommand('vscode.open', vscode.Uri.file(image));
    }
  }
  return result;
}

// The server answers { image: the path it wrote }.
function imagePath(result: unknown): string | undefined {
  if (result && typeof result === 'object' && 'image' in result) {
    const image = (result as { image: unknown }).image;
    return typeof image === 'string' ? image : undefined;
  }
  return undefined;
}
