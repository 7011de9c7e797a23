// "Check workspace": runs `povrayst check --format json` over the workspace folders and
// shows every finding in the Problems panel, including scenes that are not open.

import { execFile } from 'node:child_process';
import * as fs from 'node:fs';
import * as path from 'node:path';
import * as vscode from 'vscode';
import { CheckFinding, Settings, checkCommand } from './serverConfig';

export async function checkWorkspace(settings: Settings, collection: vscode.DiagnosticCollection): Promise<void> {
  const folders = (vscode.workspace.workspaceFolders ?? []).map((folder) => folder.uri.fsPath);
  if (folders.length === 0) {
    void vscode.window.showErrorMessage('Povrayst: open a folder to check it.');
    return;
  }
  const { command, args } = checkCommand(settings, folders);
  const stdout = await new Promise<string>((resolve, reject) => {
    // Exit status 1 only means findings; 2 is a real failure, told on stderr.
    execFile(command, args, { maxBuffer: 64 << 20 }, (error, out, err) => {
      if (error && error.code !== 1) {
        reject(new Error(err || error.message));
      } else {
        resolve(out);
      }
    });
  }).catch((error: Error) => {
    void vscode.window.showErrorMessage(`Povrayst: check failed: ${error.message}`);
    return undefined;
  });
  if (stdout === undefined) {
    return;
  }
  const findings = JSON.parse(stdout) as CheckFinding[];
  const byFile = new Map<string, vscode.Diagnostic[]>();
  for (const finding of findings) {
    // Files found on disk are named by their paths; a bundled standard include by its
    // bare name, which is no file to show, so its findings go on the Problems panel's
    // workspace entry instead.
    const resolved = path.resolve(folders[0], finding.file);
    const file = fs.existsSync(resolved) ? resolved : folders[0];
    const start = finding.range?.start ?? { line: 1, column: 1 };
    const end = finding.range?.end ?? start;
    const range = new vscode.Range(start.line - 1, start.column - 1, end.line - 1, end.column - 1);
    const place = file === resolved ? [] : [`in ${finding.file}`];
    const message = [finding.message, ...place, ...finding.notes.map((note) => `note: ${note}`)].join('\n');
    const severity =
      finding.severity === 'error' ? vscode.DiagnosticSeverity.Error : vscode.DiagnosticSeverity.Warning;
    const diagnostic = new vscode.Diagnostic(range, message, severity);
    diagnostic.source = 'povrayst check';
    if (finding.code) {
      diagnostic.code = finding.code;
    }
    byFile.set(file, [...(byFile.get(file) ?? []), diagnostic]);
  }
  collection.clear();
  for (const [file, diagnostics] of byFile) {
    collection.set(vscode.Uri.file(file), diagnostics);
  }
  const errors = findings.filter((finding) => finding.severity === 'error').length;
  void vscode.window.showInformationMessage(
    `Povrayst: ${errors} errors and ${findings.length - errors} warnings in ${folders.join(', ')}.`,
  );
}
