// Builds the browser client into dist/client: the bundle (esbuild) and the static files beside it.
import { build } from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');

export async function buildClient(outDir = resolve(ROOT, 'dist/client')): Promise<string> {
  mkdirSync(outDir, { recursive: true });
  // The game's bundle, minified (what a first visit loads), and the dev page's apart from it.
  for (const [entry, out] of [
    ['client/main.ts', 'app.js'],
    ['client/dev/main.ts', 'dev.js'],
  ] as const) {
    await build({
      entryPoints: [resolve(ROOT, entry)],
      outfile: resolve(outDir, out),
      bundle: true,
      minify: true,
      format: 'esm',
      target: 'es2022',
      sourcemap: true,
      logLevel: 'warning',
    });
  }
  // The computer's Web Worker, apart: only a page that plays the computer loads it. A classic
  // script (iife), so that it can start from a Blob held in memory when the network is off.
  await build({
    entryPoints: [resolve(ROOT, 'client/computer/worker.ts')],
    outfile: resolve(outDir, 'computer.js'),
    bundle: true,
    minify: true,
    format: 'iife',
    target: 'es2022',
    sourcemap: true,
    logLevel: 'warning',
  });
  for (const name of ['index.html', 'dev.html', 'style.css']) copyFileSync(resolve(ROOT, 'client', name), resolve(outDir, name));
  return outDir;
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const out = await buildClient();
  console.log(`client built into ${out}`);
}
