// Playing the computer in the browser: from the lobby against the server's computer (its moves
// shown, every hash the server's), and in practice against a Web Worker with the network off.
import { join } from 'node:path';
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import type { ServerMessage } from '../../shared/protocol/index.ts';
import { chromiumAvailable, launchChromium } from '../support/browser.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

type ShotMsg = Extract<ServerMessage, { type: 'shot' }>;
const hashOf = (page: Page) => page.locator('canvas.table').getAttribute('data-outcome-hash');

/** Clicks Shoot whenever it is enabled, until `done`; bounded in time. */
async function shootUntil(page: Page, done: () => Promise<boolean>, timeoutMs: number): Promise<void> {
  const shoot = page.getByRole('button', { name: 'Shoot' });
  const t0 = Date.now();
  while (!(await done())) {
    if (Date.now() - t0 > timeoutMs) throw new Error(`not done in ${timeoutMs} ms`);
    if ((await shoot.isVisible()) && (await shoot.isEnabled())) await shoot.click();
    await page.waitForTimeout(200);
  }
}

describe.skipIf(!chromiumAvailable())('playing the computer in the browser', () => {
  let browser: Browser;
  let server: ServerProcess;
  beforeAll(async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db') });
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.stop('SIGKILL');
  });

  it('from the lobby: "Play the computer" opens a game, its moves are shown, the page lands on the server\'s hashes', async () => {
    const ctx = await browser.newContext({ viewport: { width: 1100, height: 900 } });
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.url}/`);
    await page.waitForSelector('#server-status.ok');
    await page.getByLabel('Game', { exact: true }).selectOption('threecushion');
    await page.getByLabel('Level', { exact: true }).selectOption('2');
    await page.getByRole('button', { name: 'Play the computer' }).click();
    await page.waitForURL(/\/room\/[\w-]+$/);
    const roomId = page.url().split('/').at(-1)!;
    await expect.poll(() => page.getByText('Computer (level 2)').count(), { timeout: 10_000 }).toBeGreaterThan(0);
    const watcher = await ProtocolClient.connect(`${server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello', name: 'Computer-watch' });
    const seen: ServerMessage[] = [];
    watcher.onMessage((m) => seen.push(m));
    const first = await watcher.request({ type: 'watch', room: roomId });
    if (first.type !== 'room') throw new Error(JSON.stringify(first));
    const computer = first.room.players[1]!.id;
    const its = () => seen.filter((m): m is ShotMsg => m.type === 'shot' && m.shot.player === computer);
    try {
      await shootUntil(page, async () => its().length > 0, 60_000);
      // The page simulated the computer's strokes itself and landed on the server's hashes (the
      // computer may have played on after a point: the newest shot is the one shown).
      const newest = () => seen.filter((m): m is ShotMsg => m.type === 'shot').at(-1)!.outcome.hash;
      await expect.poll(async () => (await hashOf(page)) === newest(), { timeout: 20_000 }).toBe(true);
      expect(await page.evaluate(() => (window as unknown as { baizeMismatches: { mismatches: number } }).baizeMismatches.mismatches)).toBe(0);
    } finally {
      await watcher.close();
    }
    expect(errors).toEqual([]);
    await ctx.close();
  }, 120_000);

  it('in practice with the network off: the computer thinks in a Web Worker and plays', async () => {
    const ctx = await browser.newContext({ viewport: { width: 1100, height: 900 } });
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.url}/practice`);
    await page.waitForSelector('canvas.table');
    // The worker's script is fetched when the page opens; then the network goes.
    await page.waitForSelector('button[data-ready="true"]');
    await ctx.setOffline(true);
    await page.getByLabel('Game', { exact: true }).selectOption('threecushion');
    await page.getByLabel('Level', { exact: true }).selectOption('1');
    await page.getByRole('button', { name: 'Play the computer' }).click();
    await expect.poll(() => page.locator('.verdict').textContent()).toContain('against the computer (level 1)');
    const moves = async () => Number((await page.locator('canvas.table').getAttribute('data-computer-moves')) ?? 0);
    await shootUntil(page, async () => (await moves()) >= 1, 90_000);
    await expect.poll(() => page.locator('.verdict').textContent(), { timeout: 20_000 }).toMatch(/Computer \(level 1\)|you/);
    expect(errors).toEqual([]);
    await ctx.close();
  }, 120_000);
});
