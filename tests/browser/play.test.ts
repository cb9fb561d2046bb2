// The browser client against a real server: two Chromium contexts play a game through the UI (a
// break, a foul, ball in hand dragged, a concession) while Firefox watches, every page's hash
// equal to the server's; the page reconnects after the server restarts; practice plays offline;
// no page logs an error.
import { join } from 'node:path';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { cueBallId } from '../../shared/rules/index.ts';
import { tableSpec } from '../../shared/physics/index.ts';
import { chromiumAvailable, launchChromium } from '../support/browser.ts';
import { firefoxAvailable, launchFirefox } from '../support/firefox.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';
import { reportCollector } from '../support/report-collector.ts';

const RAIL = 0.09; // client/table/draw.ts

function watchErrors(page: Page, errors: string[], label: string): void {
  page.on('pageerror', (e) => errors.push(`${label}: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(`${label}: ${m.text()}`);
  });
}

const hashOf = (page: Page) => page.locator('canvas.table').getAttribute('data-outcome-hash');

describe.skipIf(!chromiumAvailable())('the browser client', () => {
  let browser: Browser;
  let server: ServerProcess;
  let dbPath: string;
  beforeAll(async () => {
    dbPath = join(tempDir(), 'baize.db');
    server = await startServerProcess({ BAIZE_DB: dbPath });
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.stop('SIGKILL');
  });

  it('two players play through the UI, a Firefox spectator watching; every page lands on the server\'s hashes', async () => {
    const errors: string[] = [];
    const [ctxA, ctxB] = [await browser.newContext({ viewport: { width: 1100, height: 900 } }), await browser.newContext({ viewport: { width: 1100, height: 900 } })];
    const a = await ctxA.newPage();
    const b = await ctxB.newPage();
    watchErrors(a, errors, 'A');
    watchErrors(b, errors, 'B');
    await a.goto(`${server.url}/`);
    await a.waitForSelector('#server-status.ok');
    await a.getByRole('button', { name: 'Create table' }).click();
    await a.waitForURL(/\/room\/[\w-]+$/);
    const roomId = a.url().split('/').at(-1)!;
    // The server's side of the story, from an outside client watching the room.
    const watcher = await ProtocolClient.connect(`${server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello', name: 'Referee-watch' });
    const seen: ServerMessage[] = [];
    watcher.onMessage((m) => seen.push(m));
    await watcher.request({ type: 'watch', room: roomId });
    const room = (): RoomView => (seen.filter((m) => m.type === 'room').at(-1) as Extract<ServerMessage, { type: 'room' }>).room;
    const shots = () => seen.filter((m): m is Extract<ServerMessage, { type: 'shot' }> => m.type === 'shot');
    /** The game as it stands: from the newest of the room and shot messages. */
    const latest = () => {
      const m = seen.filter((x) => x.type === 'room' || x.type === 'shot').at(-1)!;
      return m.type === 'room' ? { stateId: m.room.stateId, game: m.room.game! } : m.type === 'shot' ? { stateId: m.stateId, game: m.game } : null!;
    };

    const reports = await reportCollector();
    const firefox = firefoxAvailable() ? launchFirefox(`${server.url}/room/${roomId}?report=${encodeURIComponent(reports.url)}`) : undefined;
    try {
      await b.goto(`${server.url}/room/${roomId}`);
      await b.getByRole('button', { name: 'Join' }).click();
      await expect.poll(() => room().status, { timeout: 10_000 }).toBe('playing');
      if (firefox) await expect.poll(() => room().spectators, { timeout: 30_000 }).toBe(2);
      const pages = { [room().players[0]!.id]: a, [room().players[1]!.id]: b };
      const onTurn = () => pages[latest().game.turn]!;

      // The break, with the Shoot button.
      await a.getByRole('button', { name: 'Shoot' }).click();
      await expect.poll(() => shots().length, { timeout: 10_000 }).toBe(1);
      const brk = shots()[0]!;
      await expect.poll(() => hashOf(a)).toBe(brk.outcome.hash);
      await expect.poll(() => hashOf(b)).toBe(brk.outcome.hash);

      // A foul: the player on turn strokes the cue ball as softly as the keys allow, with Space.
      const fouler = onTurn();
      await fouler.waitForFunction(() => !(document.querySelector('button.shoot') as HTMLButtonElement).disabled, undefined, { timeout: 30_000 });
      const canvas = fouler.locator('canvas.table');
      await canvas.focus();
      for (let i = 0; i < 12; i++) await canvas.press('ArrowDown');
      for (let i = 0; i < 200; i++) await canvas.press('ArrowLeft');
      await canvas.press('Space');
      await expect.poll(() => shots().length, { timeout: 10_000 }).toBe(2);
      const foul = shots()[1]!;
      await expect.poll(() => hashOf(a), { timeout: 20_000 }).toBe(foul.outcome.hash);
      await expect.poll(() => hashOf(b), { timeout: 20_000 }).toBe(foul.outcome.hash);

      // That stroke is a foul (too soft to reach a rail after any contact): the opponent has the
      // ball in hand, drags it and shoots.
      expect(foul.game.verdict!.foul).toBe(true);
      {
        const g = foul.game;
        expect(g.ballInHand).toBe('anywhere');
        const taker = onTurn();
        await taker.waitForFunction(() => !(document.querySelector('button.shoot') as HTMLButtonElement).disabled, undefined, { timeout: 30_000 });
        const spec = tableSpec(g.table);
        const cue = g.balls.find((x) => x.id === cueBallId(g))!;
        const box = (await taker.locator('canvas.table').boundingBox())!;
        const scale = box.width / (spec.length + 2 * RAIL);
        const toScreen = (p: { x: number; y: number }) => ({ x: box.x + box.width / 2 + p.x * scale, y: box.y + box.height / 2 - p.y * scale });
        const from = toScreen(cue);
        const target = { x: -0.8, y: 0.3 };
        const to = toScreen(target);
        await taker.mouse.move(from.x, from.y);
        await taker.mouse.down();
        await taker.mouse.move(to.x, to.y, { steps: 8 });
        await taker.mouse.up();
        await taker.getByRole('button', { name: 'Shoot' }).click();
        await expect.poll(() => shots().length, { timeout: 10_000 }).toBe(3);
        const placed = shots()[2]!;
        expect(placed.cueBall).toBeDefined();
        expect(Math.hypot(placed.cueBall!.x - target.x, placed.cueBall!.y - target.y)).toBeLessThan(0.02);
        await expect.poll(() => hashOf(a), { timeout: 30_000 }).toBe(placed.outcome.hash);
        await expect.poll(() => hashOf(b), { timeout: 30_000 }).toBe(placed.outcome.hash);
      }

      // A concedes; both pages say who won (once the last shot's balls have stopped there).
      await a.getByRole('button', { name: 'Concede' }).click();
      await a.getByRole('button', { name: 'Really concede? Click again' }).click();
      await expect.poll(() => room().status, { timeout: 10_000 }).toBe('over');
      const winner = room().players.find((p) => p.id === room().winner)!.name;
      for (const page of [a, b]) await expect.poll(() => page.locator('.verdict').textContent(), { timeout: 30_000 }).toContain(`${winner} wins`);

      // Firefox simulated every shot itself and landed on the server's hashes.
      if (firefox) {
        await expect.poll(() => reports.got.length, { timeout: 60_000 }).toBe(shots().length).catch((err: Error) => {
          throw new Error(`${err.message}: Firefox reported ${JSON.stringify(reports.got.map((r) => [r.stateId, r.hash]))} of ${JSON.stringify(shots().map((m) => m.stateId))}`);
        });
        for (const r of reports.got) {
          expect(r.userAgent).toMatch(/Firefox\//);
          expect(r.hash).toBe(shots().find((s) => s.stateId === r.stateId)!.outcome.hash);
        }
      }
      expect(await a.evaluate(() => (window as unknown as { baizeMismatches: { mismatches: number } }).baizeMismatches.mismatches)).toBe(0);
      expect(await b.evaluate(() => (window as unknown as { baizeMismatches: { mismatches: number } }).baizeMismatches.mismatches)).toBe(0);
      expect(errors).toEqual([]);
    } finally {
      firefox?.kill('SIGKILL');
      await reports.close();
      await watcher.close(200);
      await ctxA.close();
      await ctxB.close();
    }
  }, 180_000);

  it('says it is reconnecting when the server goes away, and resumes the seat when it is back', async () => {
    const ctx: BrowserContext = await browser.newContext();
    const page = await ctx.newPage();
    await page.goto(`${server.url}/`);
    await page.waitForSelector('#server-status.ok');
    await page.getByRole('button', { name: 'Create table' }).click();
    await page.waitForURL(/\/room\//);
    await expect.poll(() => page.locator('.verdict').textContent()).toBe('Waiting for an opponent.');
    const port = new URL(server.url).port;
    await server.stop('SIGKILL');
    await expect.poll(() => page.locator('#server-status').textContent(), { timeout: 10_000 }).toBe('Reconnecting…');
    expect(await page.locator('.banner').textContent()).toContain('reconnecting');
    server = await startServerProcess({ BAIZE_DB: dbPath, PORT: port });
    await expect.poll(() => page.locator('#server-status').getAttribute('class'), { timeout: 20_000 }).toBe('ok');
    await expect.poll(() => page.locator('.banner').textContent()).toBe('');
    // The same player, still seated in the same room.
    await expect.poll(() => page.locator('.players li').first().textContent()).toContain('(you)');
    await ctx.close();
  }, 60_000);

  it('plays practice with the network off once loaded', async () => {
    const ctx = await browser.newContext();
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${server.url}/practice`);
    await page.waitForSelector('canvas.table');
    await ctx.setOffline(true);
    await page.getByRole('button', { name: 'Shoot' }).click();
    await expect.poll(() => hashOf(page), { timeout: 10_000 }).toMatch(/^[0-9a-f]{16}$/);
    // The shot's verdict once its balls have stopped, then undone.
    await expect.poll(() => page.locator('.verdict').textContent(), { timeout: 20_000 }).not.toMatch(/^Free practice/);
    await page.getByRole('button', { name: 'Undo' }).click();
    await expect.poll(() => page.locator('.verdict').textContent()).toBe('Shot undone.');
    expect(errors).toEqual([]);
    await ctx.close();
  }, 60_000);

  it('shows every page without an error in the console', async () => {
    const ctx = await browser.newContext();
    const page = await ctx.newPage();
    const errors: string[] = [];
    watchErrors(page, errors, 'page');
    await page.goto(`${server.url}/`);
    await page.waitForSelector('#server-status.ok');
    await page.getByRole('button', { name: 'Create table' }).click();
    await page.waitForURL(/\/room\//);
    for (const path of ['/', '/practice', '/leaderboard', '/leaderboard?kind=snooker', '/player/1', '/match/1', '/dev.html']) {
      await page.goto(`${server.url}${path}`);
      await page.waitForLoadState('networkidle');
    }
    // The first test's match, replayed in this browser from its record, lands on every hash.
    await page.goto(`${server.url}/match/1`);
    await expect.poll(() => page.locator('section').first().textContent(), { timeout: 20_000 }).toContain("every hash matches the server's");
    await page.getByRole('button', { name: 'Play' }).click();
    await expect.poll(() => page.locator('canvas.table').getAttribute('data-outcome-hash'), { timeout: 20_000 }).toMatch(/^[0-9a-f]{16}$/);
    expect(errors).toEqual([]);
    await ctx.close();
  }, 60_000);
});
