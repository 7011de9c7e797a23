// The Povrayst extension: starts `povrayst lsp` for POV-Ray scenes and for Typst
// documents (which the server serves inside their povray blocks), and adds two commands,
// "Render scene" with a preview that follows saves, and "Check workspace".

import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions, TransportKind } from 'vscode-languageclient/node';
import { Settings, documentSelector, initializationOptions, serverCommand } from './serverConfig';
import { checkWorkspace } from './checkWorkspace';
import { RenderPreview } from './renderPreview';

let client: LanguageClient | undefined;

/** The `povrayst.*` settings. */
export function readSettings(): Settings {
  const config = vscode.workspace.getConfiguration('povrayst');
  return {
    serverPath: config.get<string>('server.path', 'povrayst'),
    libraryPaths: config.get<string[]>('libraryPaths', []),
    budgets: {
      loopIterations: config.get<number>('budgets.loopIterations', 10_000_000),
      macroDepth: config.get<number>('budgets.macroDepth', 1000),
      steps: config.get<number>('budgets.steps', 200_000_000),
    },
  };
}

function startClient(settings: Settings): LanguageClient {
  const { command, args } = serverCommand(settings);
  const executable = { command, args, transport: TransportKind.stdio };
  const serverOptions: ServerOptions = { run: executable, debug: executable };
  const clientOptions: LanguageClientOptions = {
    documentSelector,
    initializationOptions: initializationOptions(settings),
    synchronize: {
      fileEvents: vscode.workspace.createFileSystemWatcher('**/*.{pov,inc,mcr,mac}'),
    },
  };
  const started = new LanguageClient('povrayst', 'Povrayst', serverOptions, clientOptions);
  void started.start();
  return started;
}

export function activate(context: vscode.ExtensionContext): void {
  client = startClient(readSettings());
  const diagnostics = vscode.languages.createDiagnosticCollection('povrayst check');
  const preview = new RenderPreview(() => client);
  context.subscriptions.push(
    diagnostics,
    preview,
    vscode.commands.registerCommand('povrayst.renderScene', () => preview.show()),
    vscode.commands.registerCommand('povrayst.checkWorkspace', () => checkWorkspace(readSettings(), diagnostics)),
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (!event.affectsConfiguration('povrayst')) {
        return;
      }
      const settings = readSettings();
      if (event.affectsConfiguration('povrayst.server.path')) {
        // A new executable needs a new server.
        await client?.stop();
        client = startClient(settings);
      } else {
        await client?.sendNotification('workspace/didChangeConfiguration', {
          settings: initializationOptions(settings),
        });
      }
    }),
  );
}

export async function deactivate(): Promise<void> {
  await client?.stop();
}
