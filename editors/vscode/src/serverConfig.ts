// How the extension starts and configures the language server, kept free of the `vscode`
// module so that a plain Node test can start the server exactly as the extension does.

/** The extension's settings, as read from the `povrayst.*` configuration. */
export interface Settings {
  /** The `povrayst` executable. */
  serverPath: string;
  /** Directories searched for includes after the scene's own (POV-Ray's `+L`). */
  libraryPaths: string[];
  budgets: {
    loopIterations: number;
    macroDepth: number;
    steps: number;
  };
}

/** The documents the server is started for: scenes, and Typst documents for their povray blocks. */
export const documentSelector = [
  { language: 'povray' },
  { language: 'typst' },
];

/** The command line of the language server: `povrayst lsp`, speaking LSP on stdio. */
export function serverCommand(settings: Settings): { command: string; args: string[] } {
  return { command: settings.serverPath, args: ['lsp'] };
}

/** What the server is told in `initialize` and in `workspace/didChangeConfiguration`. */
export function initializationOptions(settings: Settings): object {
  return {
    libraryPaths: settings.libraryPaths,
    budgets: settings.budgets,
  };
}

/** The command line of `povrayst check` over some folders, as JSON on stdout. */
export function checkCommand(settings: Settings, folders: string[]): { command: string; args: string[] } {
  const args = ['check', '--format', 'json'];
  for (const path of settings.libraryPaths) {
    args.push('-L', path);
  }
  return { command: settings.serverPath, args: [...args, ...folders] };
}

/** One finding of `povrayst check --format json`. */
export interface CheckFinding {
  code: string | null;
  severity: 'error' | 'warning';
  message: string;
  file: string;
  range: { start: { line: number; column: number }; end: { line: number; column: number } } | null;
  notes: string[];
}
