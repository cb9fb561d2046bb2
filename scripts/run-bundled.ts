// Runs a TypeScript entry point as one esbuild bundle, the way the browser client runs the shared
// code: no per-module loader in the way of what a benchmark measures.
//   node --import tsx scripts/run-bundled.ts bench/sim.ts [args...]
import { build } from 'esbuild';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const entry = process.argv[2];
if (!entry) {
  console.error('usage: run-bundled.ts <entry.ts> [args...]');
  process.exit(2);
}
const dir = mkdtempSync(join(tmpdir(), 'baize-bundle-'));
const outfile = join(dir, 'main.mjs');
// The bundle is removed when the process exits (a killed run can still leave it behind).
process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
await build({
  entryPoints: [resolve(entry)],
  outfile,
  bundle: true,
  platform: 'node',
  format: 'esm',
  target: 'node20',
  packages: 'external',
  logLevel: 'warning',
});
process.argv.splice(2, 1);
await import(pathToFileURL(outfile).href);
