// "Check workspace" runs the command line of src/serverConfig.ts and reads its JSON; this
// runs the same command over a folder and checks the findings have the shape it reads.

import { test } from 'node:test';
import * as assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import * as fs from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';
import { CheckFinding, Settings, checkCommand } from '../src/serverConfig';

const settings: Settings = {
  serverPath: process.env.POVRAYST ?? 'povrayst',
  libraryPaths: [],
  budgets: { loopIterations: 10_000_000, macroDepth: 1000, steps: 200_000_000 },
};

test('check over a folder gives findings with files, places and codes', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'povrayst-check-'));
  try {
    fs.mkdirSync(path.join(dir, 'scenes'));
    fs.writeFileSync(path.join(dir, 'scenes', 'ok.pov'), '#version 3.7; global_settings { assumed_gamma 1 }\n#declare Unused = 1;\nsphere { 0, 1 }\n');
    fs.writeFileSync(path.join(dir, 'broken.pov'), '#version 3.7;\nsphere { 0, Raduis }\n');
    const { command, args } = checkCommand(settings, [dir]);
    let stdout = '';
    try {
      execFileSync(command, args, { encoding: 'utf8' });
      assert.fail('a scene with an error must fail the check');
    } catch (error) {
      const failed = error as { status: number; stdout: string };
      assert.equal(failed.status, 1);
      stdout = failed.stdout;
    }
    const findings = (JSON.parse(stdout) as CheckFinding[]).map((finding) => ({
      file: path.relative(dir, finding.file),
      code: finding.code,
      severity: finding.severity,
      message: finding.message,
      start: finding.range?.start,
    }));
    assert.deepEqual(findings, [
      {
        file: 'broken.pov',
        code: null,
        severity: 'error',
        message: "undeclared identifier 'Raduis'",
        start: { line: 2, column: 13 },
      },
      {
        file: path.join('scenes', 'ok.pov'),
        code: 'unused-declaration',
        severity: 'warning',
        message: "'Unused' is declared by #declare but never used",
        start: { line: 2, column: 10 },
      },
    ]);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
