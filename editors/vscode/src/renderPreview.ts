// "Render scene": a webview beside the editor showing the scene rendered by the language
// server (`povrayst/render`), rendered again each time the scene or one of its includes
// is saved. A scene with errors shows the errors instead.

import * as vscode from 'vscode';
import { LanguageClient } from 'vscode-languageclient/node';

interface RenderResult {
  png: string;
  width: number;
  height: number;
}

export class RenderPreview implements vscode.Disposable {
  private panel: vscode.WebviewPanel | undefined;
  private scene: vscode.Uri | undefined;
  private readonly onSave: vscode.Disposable;

  constructor(private readonly client: () => LanguageClient | undefined) {
    this.onSave = vscode.workspace.onDidSaveTextDocument((document) => {
      if (this.panel && this.scene && document.languageId === 'povray') {
        void this.refresh();
      }
    });
  }

  /** Opens (or reveals) the preview for the active POV-Ray editor. */
  async show(): Promise<void> {
    const editor = vscode.window.activeTextEditor;
    if (!editor || editor.document.languageId !== 'povray') {
      void vscode.window.showErrorMessage('Povrayst: open a POV-Ray scene to render it.');
      return;
    }
    this.scene = editor.document.uri;
    if (!this.panel) {
      this.panel = vscode.window.createWebviewPanel('povraystPreview', 'Render preview', vscode.ViewColumn.Beside, {
        enableScripts: false,
      });
      this.panel.onDidDispose(() => {
        this.panel = undefined;
      });
    } else {
      this.panel.reveal(vscode.ViewColumn.Beside, true);
    }
    await this.refresh();
  }

  private async refresh(): Promise<void> {
    const client = this.client();
    if (!this.panel || !this.scene || !client) {
      return;
    }
    const config = vscode.workspace.getConfiguration('povrayst');
    const name = vscode.workspace.asRelativePath(this.scene);
    this.panel.title = `Render: ${name}`;
    try {
      const result = await client.sendRequest<RenderResult>('povrayst/render', {
        textDocument: { uri: this.scene.toString() },
        width: config.get<number>('preview.width', 320),
        height: config.get<number>('preview.height', 240),
      });
      this.panel.webview.html = page(
        `<img alt="${escape(name)}" width="${result.width}" height="${result.height}" src="data:image/png;base64,${result.png}">`,
      );
    } catch (error) {
      const message = error instanceof Error ? error.message : String(error);
      this.panel.webview.html = page(`<pre>${escape(message)}</pre>`);
    }
  }

  dispose(): void {
    this.onSave.dispose();
    this.panel?.dispose();
  }
}

function page(body: string): string {
  return `<!DOCTYPE html><html><head><meta charset="utf-8"><meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src data:; style-src 'unsafe-inline';"><style>img { image-rendering: pixelated; max-width: 100%; }</style></head><body>${body}</body></html>`;
}

function escape(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}
