// Grammar snapshot tests with vscode-tmgrammar-test: tokenizes the gallery scenes (kept
// in ../../gallery, not copied here) and the documents in test/grammar, and compares the
// scopes with the snapshots in test/grammar/snapshots. `--update` rewrites the snapshots.
// Typst and Markdown documents are tokenized with stand-in host grammars
// (test/fixtures), so that the snapshots show what our injection grammar does.

import { execFileSync } from 'node:child_process';
import * as fs from 'node:fs';
import * as os from 'node:os';
import * as path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const extension = path.dirname(here);
const gallery = path.resolve(extension, '../../gallery');
const own = path.join(here, 'grammar');
const snapshots = path.join(own, 'snapshots');
const update = process.argv.includes('--update');

const hosts = {
  '.pov': { scope: 'source.povray', grammars: [] },
  '.typ': { scope: 'source.typst', grammars: ['typst.tmLanguage.json'] },
  '.md': { scope: 'text.html.markdown', grammars: ['markdown.tmLanguage.json'] },
};

const cases = [
  ...fs.readdirSync(gallery).filter((name) => name.endsWith('.pov')).map((name) => ({ source: path.join(gallery, name), name: `gallery-${name}` })),
  ...fs.readdirSync(own).filter((name) => path.extname(name) in hosts).map((name) => ({ source: path.join(own, name), name })),
];

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'povrayst-grammar-'));
let passed = 0;
let failed = 0;
try {
  for (const { source, name } of cases) {
    const host = hosts[path.extname(name)];
    const copy = path.join(work, name);
    fs.copyFileSync(source, copy);
    const snapshot = path.join(snapshots, `${name}.snap`);
    if (fs.existsSync(snapshot)) {
      fs.copyFileSync(snapshot, `${copy}.snap`);
    } else if (!update) {
      console.error(`not ok: ${name}: no snapshot; run npm run test:update-snapshots`);
      failed++;
      continue;
    }
    const args = ['--config', path.join(extension, 'package.json'), '--scope', host.scope];
    for (const grammar of host.grammars) {
      args.push('--grammar', path.join(here, 'fixtures', grammar));
    }
    if (update) {
      args.push('--updateSnapshot');
    }
    try {
      execFileSync(path.join(extension, 'node_modules', '.bin', 'vscode-tmgrammar-snap'), [...args, copy], {
        stdio: ['ignore', 'pipe', 'pipe'],
      });
      if (update) {
        fs.mkdirSync(snapshots, { recursive: true });
        fs.copyFileSync(`${copy}.snap`, snapshot);
      }
      passed++;
    } catch (error) {
      console.error(`not ok: ${name}\n${error.stdout}${error.stderr}`);
      failed++;
    }
  }
} finally {
  fs.rmSync(work, { recursive: true, force: true });
}
console.log(`grammar snapshots: ${passed} passed, ${failed} failed`);
process.exitCode = failed === 0 && passed > 0 ? 0 : 1;
