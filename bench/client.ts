// npm run bench:client — what a first visit costs and how smoothly a shot animates, in Debian's
// Chromium against the real server: the gzipped bytes of the page, its bundle and styles; first
// contentful paint over several loads; and frame times while a full snooker break animates, beside
// an empty animation loop in the same page as the yardstick. Prints tables; asserts nothing.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { buildClient } from '../scripts/build-client.ts';
import { CORPUS } from '../shared/scenes/index.ts';
import { launchChromium } from '../tests/support/browser.ts';
import { startServerProcess, tempDir } from '../tests/support/server-process.ts';

const LOADS = 7;
const out = await buildClient();
const firstVisit = ['index.html', 'style.css', 'app.js'];
const sizes = firstVisit.map((f) => {
  const body = readFileSync(join(out, f));
  return { file: f, raw: body.length, gzip: gzipSync(body, { level: 9 }).length };
});
const dev = readFileSync(join(out, 'dev.js'));

const server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db') });
const browser = await launchChromium();
const pct = (xs: number[], p: number) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor((p / 100) * xs.length))]!;
try {
  const paints: number[] = [];
  for (let i = 0; i < LOADS; i++) {
    const ctx = await browser.newContext();
    const page = await ctx.newPage();
    await page.goto(`${server.url}/`);
    await page.waitForSelector('#server-status.ok');
    paints.push(await page.evaluate(() => performance.getEntriesByType('paint').find((e) => e.name === 'first-contentful-paint')?.startTime ?? NaN));
    await ctx.close();
  }

  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  await page.goto(`${server.url}/dev.html`);
  // The yardstick: an animation loop that draws nothing, for as long as the break takes.
  // (A string, not a function: the TypeScript loader would add helpers the page does not have.)
  const idle = (await page.evaluate(`new Promise((resolve) => {
    const times = [];
    let last = performance.now();
    function step(now) {
      times.push(now - last);
      last = now;
      if (times.length < 300) requestAnimationFrame(step);
      else resolve(times.slice(1));
    }
    requestAnimationFrame(step);
  })`)) as number[];
  const index = CORPUS.findIndex((c) => c.tags.includes('snooker-break'));
  await page.selectOption('#replay-case', String(index));
  await page.evaluate(() => ((window as unknown as { baizeFrames: number[] }).baizeFrames.length = 0));
  await page.click('#replay-play');
  await page.waitForFunction(() => document.getElementById('replay-info')?.dataset.done === 'true', undefined, { timeout: 60_000 });
  const frames = (await page.evaluate(() => (window as unknown as { baizeFrames: number[] }).baizeFrames)).slice(1);

  // The lab: time from a changed input to every figure, the rebound and the shot drawn again
  // (the page's own measure, data-redraw-ms), for a constant (all figures and the shot) and for
  // the incoming ball (Fig. 12 and the rebound only).
  await page.goto(`${server.url}/lab`);
  await page.waitForSelector('#fig12 svg');
  const redraws = async (label: string, values: number[]): Promise<number[]> => {
    const out: number[] = [];
    for (const v of values) {
      await page.getByRole('spinbutton', { name: label }).fill(String(v));
      await page.waitForFunction((q) => new URL(location.href).searchParams.get(q.key) === q.v, { key: label === 'restitution' ? 'ee' : 'alpha', v: String(v) });
      out.push(Number(await page.evaluate(() => document.getElementById('app')!.dataset.redrawMs)));
    }
    return out;
  };
  const labConstants = await redraws('restitution', Array.from({ length: 20 }, (_, i) => 0.5 + i * 0.02));
  const labBall = await redraws('incidence', Array.from({ length: 20 }, (_, i) => 20 + i * 2));

  console.log(`# bench:client (${new Date().toISOString().slice(0, 10)}, Chromium headless, ${process.platform})\n`);
  console.log('## What a first visit loads (goal: under 100 KB gzipped)\n');
  console.log('| file | bytes | gzipped |');
  console.log('|---|---|---|');
  for (const s of sizes) console.log(`| ${s.file} | ${s.raw.toLocaleString('en')} | ${s.gzip.toLocaleString('en')} |`);
  const total = sizes.reduce((n, s) => n + s.gzip, 0);
  console.log(`| **all** | ${sizes.reduce((n, s) => n + s.raw, 0).toLocaleString('en')} | **${total.toLocaleString('en')} (${(total / 1024).toFixed(1)} KB)** |`);
  console.log(`\nThe debug corpus page's bundle (dev.js, not loaded by the game) is ${dev.length.toLocaleString('en')} bytes, ${gzipSync(dev, { level: 9 }).length.toLocaleString('en')} gzipped.\n`);
  console.log(`## First contentful paint of the lobby over ${LOADS} fresh loads\n`);
  console.log(`median ${pct(paints, 50).toFixed(0)} ms, min ${Math.min(...paints).toFixed(0)} ms, max ${Math.max(...paints).toFixed(0)} ms\n`);
  console.log('## The lab: a change redrawn (goal: within 50 ms), 20 changes each\n');
  console.log('| change | median ms | p90 ms | max ms |');
  console.log('|---|---|---|---|');
  for (const [name, xs] of [['a constant (Figs. 9, 10, 12, the rebound, the shot)', labConstants], ['the incoming ball (Fig. 12, the rebound)', labBall]] as const) {
    console.log(`| ${name} | ${pct(xs, 50).toFixed(1)} | ${pct(xs, 90).toFixed(1)} | ${Math.max(...xs).toFixed(1)} |`);
  }
  console.log('');
  console.log(`## Frame times while "${CORPUS[index]!.name}" animates (${frames.length} frames), against an empty loop\n`);
  console.log('| loop | frames | median ms | p95 ms | p99 ms | max ms | frames over 20 ms |');
  console.log('|---|---|---|---|---|---|---|');
  for (const [name, xs] of [['empty rAF loop (yardstick)', idle], ['snooker break, sampled and drawn each frame', frames]] as const) {
    console.log(`| ${name} | ${xs.length} | ${pct(xs, 50).toFixed(1)} | ${pct(xs, 95).toFixed(1)} | ${pct(xs, 99).toFixed(1)} | ${Math.max(...xs).toFixed(1)} | ${xs.filter((x) => x > 20).length} |`);
  }
} finally {
  await browser.close();
  await server.stop('SIGKILL');
}
