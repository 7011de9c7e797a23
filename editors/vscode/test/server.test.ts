// Starts the language server exactly as the extension's client does (the same command
// line and initialization options, from src/serverConfig.ts) and checks that a broken
// scene gets its diagnostic. The server is the `povrayst` named by $POVRAYST, or the one
// on the PATH.

import { test } from 'node:test';
import * as assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import * as fs from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';
import { pathToFileURL } from 'node:url';
import { StreamMessageReader, StreamMessageWriter, createMessageConnection } from 'vscode-jsonrpc/node';
import { Settings, documentSelector, initializationOptions, serverCommand } from '../src/serverConfig';

const settings: Settings = {
  serverPath: process.env.POVRAYST ?? 'povrayst',
  libraryPaths: [],
  budgets: { loopIterations: 10_000_000, macroDepth: 1000, steps: 200_000_000 },
};

interface Diagnostic {
  range: { start: { line: number; character: number }; end: { line: number; character: number } };
  severity: number;
  message: string;
}

test('a broken scene gets its diagnostic from the server the extension starts', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'povrayst-vscode-'));
  const scene = path.join(dir, 'broken.pov');
  const text = '#version 3.7;\n#declare Radius = 1;\nsphere { 0, Raduis }\n';
  fs.writeFileSync(scene, text);
  const uri = pathToFileURL(scene).href;

  const { command, args } = serverCommand(settings);
  assert.deepEqual(args, ['lsp']);
  const server = spawn(command, args, { stdio: ['pipe', 'pipe', 'inherit'] });
  const connection = createMessageConnection(
    new StreamMessageReader(server.stdout),
    new StreamMessageWriter(server.stdin),
  );
  const published = new Promise<Diagnostic[]>((resolve) => {
    connection.onNotification('textDocument/publishDiagnostics', (params: { uri: string; diagnostics: Diagnostic[] }) => {
      if (params.uri === uri && params.diagnostics.length > 0) {
        resolve(params.diagnostics);
      }
    });
  });
  connection.listen();
  try {
    const initialized = await connection.sendRequest<{ serverInfo?: { name: string } }>('initialize', {
      processId: process.pid,
      rootUri: pathToFileURL(dir).href,
      capabilities: {},
      initializationOptions: initializationOptions(settings),
    });
    assert.equal(initialized.serverInfo?.name, 'povrayst');
    await connection.sendNotification('initialized', {});
    assert.ok(documentSelector.some((selector) => selector.language === 'povray'));
    await connection.sendNotification('textDocument/didOpen', {
      textDocument: { uri, languageId: 'povray', version: 1, text },
    });
    // Besides the error, the server may add hints (an unused declaration here).
    const errors = (await published).filter((diagnostic) => diagnostic.severity === 1);
    assert.equal(errors.length, 1);
    assert.match(errors[0].message, /^undeclared identifier 'Raduis'/);
    assert.deepEqual(errors[0].range, {
      start: { line: 2, character: 12 },
      end: { line: 2, character: 18 },
    });
    await connection.sendRequest('shutdown');
    await connection.sendNotification('exit');
  } finally {
    connection.dispose();
    server.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
