// Builds the browser client into dist/client: the bundle (esbuild) and the static files beside it.
import { build } from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '..');

export async function buildClient(outDir = resolve(ROOT, 'dist/client')): Promise<string> {
  mkdirSync(outDir, { recursive: true });
  await build({
    entryPoints: [resolve(ROOT, 'client/main.ts')],
    outfile: resolve(outDir, 'app.js'),
    bundle: true,
    format: 'esm',
    target: 'es2022',
    sourcemap: true,
    logLevel: 'warning',
  });
  for (const name of ['index.html', 'style.css']) copyFileSync(resolve(ROOT, 'client', name), resolve(outDir, name));
  return outDir;
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const out = await buildClient();
  console.log(`client built into ${out}`);
}
