// Whole games through the pages as players play them: two Chromium players play a nine-ball rack
// to its end by the rules, every stroke aimed with a click and played by dragging the cue back from
// the cue ball, fast-forwarded by both, while a Firefox spectator simulates every shot itself; the
// end is a result dialog with the rating change. The shot each player goes for comes from the
// bots' "sound" strategy run on the server's game; what the drag plays is what counts.
import { join } from 'node:path';
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import { botShot } from '../../bots/strategy.ts';
import { fullPull, MAX_SPEED } from '../../client/table/cue.ts';
import { simulate } from '../../shared/physics/index.ts';
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { cueBallId, type Game } from '../../shared/rules/index.ts';
import { chromiumAvailable, launchChromium } from '../support/browser.ts';
import { firefoxAvailable, launchFirefox } from '../support/firefox.ts';
import { reportCollector } from '../support/report-collector.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';
import { tableOnScreen, type TableOnScreen } from '../support/table-screen.ts';

type ShotMessage = Extract<ServerMessage, { type: 'shot' }>;

const hashOf = (page: Page) => page.locator('canvas.table').getAttribute('data-outcome-hash');
const mismatches = (page: Page) => page.evaluate(() => (window as unknown as { baizeMismatches: { mismatches: number } }).baizeMismatches.mismatches);

/** The farthest point (up to `max` px) from `from` along `angle` (screen radians, y down) that stays inside the box with a margin. */
function along(t: TableOnScreen, from: { x: number; y: number }, angle: number, max: number): { x: number; y: number } {
  const m = 6;
  let d = max;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  if (c > 0) d = Math.min(d, (t.box.x + t.box.width - m - from.x) / c);
  if (c < 0) d = Math.min(d, (t.box.x + m - from.x) / c);
  if (s > 0) d = Math.min(d, (t.box.y + t.box.height - m - from.y) / s);
  if (s < 0) d = Math.min(d, (t.box.y + m - from.y) / s);
  return { x: from.x + d * c, y: from.y + d * s };
}

/**
 * Aims the page's cue at `heading` with clicks and plays `speed` by dragging back from the cue
 * ball. A first click across the line turns the cue away, so that the aiming click never lands
 * on the stick (a press there would start a stroke).
 */
async function strokeByDrag(page: Page, game: Game, heading: number, speed: number): Promise<void> {
  const t = await tableOnScreen(page, game.table);
  const cue = game.balls.find((b) => b.id === cueBallId(game))!;
  const from = t.at(cue);
  const screen = -heading; // the table's y is up, the screen's down
  const minAway = 3 * t.scale * 0.03; // clear of the cue ball (the page ignores a hover on it)
  const across = [screen + Math.PI / 2, screen - Math.PI / 2]
    .map((a) => along(t, from, a, 120))
    .sort((p, q) => Math.hypot(q.x - from.x, q.y - from.y) - Math.hypot(p.x - from.x, p.y - from.y))[0]!;
  if (Math.hypot(across.x - from.x, across.y - from.y) > minAway) await page.mouse.click(across.x, across.y);
  const ahead = along(t, from, screen, 2000);
  await page.mouse.click(ahead.x, ahead.y);
  // The pull for the speed (client/table/cue.ts: proportional, full power at fullPull).
  const pull = (speed / MAX_SPEED) * fullPull(t.scale) * t.scale + 1;
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x - (pull / 2) * Math.cos(screen), from.y - (pull / 2) * Math.sin(screen), { steps: 3 });
  await page.mouse.move(from.x - pull * Math.cos(screen), from.y - pull * Math.sin(screen), { steps: 3 });
  await page.mouse.up();
}

describe.skipIf(!chromiumAvailable())('whole games in the browser', () => {
  let browser: Browser;
  let server: ServerProcess;
  beforeAll(async () => {
    // A rated match needs 60 s of play by default: not worth waiting for here.
    server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db'), BAIZE_RATED_MIN_PLAY_S: '0' });
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.stop('SIGKILL');
  });

  async function player(): Promise<Page> {
    const ctx = await browser.newContext({ viewport: { width: 1100, height: 900 } });
    const page = await ctx.newPage();
    await page.goto(`${server.url}/`);
    await page.waitForSelector('#server-status.ok');
    return page;
  }

  /** A nine-ball table opened by a and joined by b, watched by an outside client (the server's story). */
  async function table(a: Page, b: Page, raceTo = 1) {
    await a.getByLabel('Game').selectOption('nineball');
    await a.getByLabel('Race to').fill(String(raceTo));
    await a.getByRole('button', { name: 'Create table' }).click();
    await a.waitForURL(/\/room\/[\w-]+$/);
    const id = a.url().split('/').at(-1)!;
    const watcher = await ProtocolClient.connect(`${server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello' });
    const seen: ServerMessage[] = [];
    watcher.onMessage((m) => seen.push(m));
    await watcher.request({ type: 'watch', room: id });
    const room = (): RoomView => (seen.filter((m) => m.type === 'room').at(-1) as Extract<ServerMessage, { type: 'room' }>).room;
    const shots = () => seen.filter((m): m is ShotMessage => m.type === 'shot');
    const latest = (): Game => {
      const m = seen.filter((x) => x.type === 'room' || x.type === 'shot').at(-1)!;
      return m.type === 'room' ? m.room.game! : (m as ShotMessage).game;
    };
    await b.goto(`${server.url}/room/${id}`);
    await b.getByRole('button', { name: 'Join' }).click();
    await expect.poll(() => room().status, { timeout: 10_000 }).toBe('playing');
    return { id, watcher, room, shots, latest };
  }

  /** The player on turn plays the bots' choice by drag; both players fast-forward it to its end. */
  async function playOne(pages: Record<string, Page>, latest: () => Game, shots: () => ShotMessage[]): Promise<void> {
    const g = latest();
    const page = pages[g.turn]!;
    await expect.poll(() => page.getByRole('button', { name: 'Shoot' }).isEnabled(), { timeout: 30_000 }).toBe(true);
    const { shot } = botShot(g, simulate);
    const before = shots().length;
    await strokeByDrag(page, g, shot.heading, shot.speed);
    await expect.poll(() => shots().length, { timeout: 10_000, message: `shot ${before + 1} was not played by its drag` }).toBe(before + 1);
    const played = shots().at(-1)!;
    expect(played.shot.heading).toBeCloseTo(shot.heading, 1);
    // Both players skip to the end of the shot: x2, x4, the end (the F key).
    const all = Object.values(pages);
    for (const p of all) for (let i = 0; i < 3; i++) await p.keyboard.press('f');
    for (const p of all) await expect.poll(() => hashOf(p), { timeout: 20_000 }).toBe(played.outcome.hash);
  }

  it('two players play a nine-ball rack to its end by dragging the cue, a Firefox spectator landing on every hash; the result dialog ends it', async () => {
    const a = await player();
    const b = await player();
    const errors: string[] = [];
    for (const [page, label] of [[a, 'A'], [b, 'B']] as const) {
      page.on('pageerror', (e) => errors.push(`${label}: ${e.message}`));
      page.on('console', (m) => void (m.type() === 'error' && errors.push(`${label}: ${m.text()}`)));
    }
    const { id, watcher, room, shots, latest } = await table(a, b);
    const reports = await reportCollector();
    const firefox = firefoxAvailable() ? launchFirefox(`${server.url}/room/${id}?report=${encodeURIComponent(reports.url)}`) : undefined;
    try {
      if (firefox) await expect.poll(() => room().spectators, { timeout: 30_000 }).toBe(2);
      const pages: Record<string, Page> = { [room().players[0]!.id]: a, [room().players[1]!.id]: b };
      const CAP = 80;
      while (room().status === 'playing' && shots().length < CAP) await playOne(pages, latest, shots);
      expect(room().status, `the rack did not end in ${CAP} shots`).toBe('over');
      const g = latest();
      expect(g.winner).not.toBeNull();
      expect(g.verdict?.loss).not.toBe('concession');
      const winner = room().players.find((p) => p.id === room().winner)!.name;
      for (const p of [a, b]) {
        const dialog = p.getByRole('dialog');
        await expect.poll(() => dialog.isVisible(), { timeout: 30_000 }).toBe(true);
        expect(await dialog.textContent()).toMatch(new RegExp(`You win|${winner} wins`));
        expect(await dialog.getByRole('button', { name: 'Rematch' }).isVisible()).toBe(true);
        expect(await dialog.getByRole('button', { name: 'Lobby' }).isVisible()).toBe(true);
        expect(await p.getByRole('button', { name: 'Shoot' }).count()).toBe(0);
        // The rating change when rated, else why not (a rack can end before both took 3 shots).
        const lines = await dialog.getByRole('list', { name: 'Rating' }).locator('li').allTextContents();
        if (room().rated === false) expect(lines.join(' ')).toMatch(/^Not rated: /);
        else await expect.poll(() => dialog.getByRole('list', { name: 'Rating' }).locator('li').allTextContents(), { timeout: 10_000 }).toEqual([expect.stringMatching(/\d+ → \d+ \([+−]\d+\)$/), expect.stringMatching(/\d+ → \d+ \([+−]\d+\)$/)]);
        expect(await mismatches(p)).toBe(0);
      }
      if (firefox) {
        await expect.poll(() => reports.got.length, { timeout: 120_000 }).toBe(shots().length);
        for (const r of reports.got) {
          expect(r.userAgent).toMatch(/Firefox\//);
          expect(r.hash).toBe(shots().find((s) => s.stateId === r.stateId)!.outcome.hash);
        }
      }
      expect(errors).toEqual([]);
      console.log(`nine-ball by drag: ${shots().length} shots, won by ${g.verdict?.message}`);
    } finally {
      firefox?.kill('SIGKILL');
      await reports.close();
      await watcher.close(200);
      await a.context().close();
      await b.context().close();
    }
  }, 300_000);
  it('a rated match\'s result dialog shows each player\'s rating before and after, as the server stored it', async () => {
    const a = await player();
    const b = await player();
    const { watcher, room, shots, latest } = await table(a, b, 3);
    try {
      const pages: Record<string, Page> = { [room().players[0]!.id]: a, [room().players[1]!.id]: b };
      const taken = (pid: string) => shots().filter((s) => s.shot.player === pid).length;
      // Three shots each (a race to 3 racks does not end first), then the player on turn concedes.
      while (Object.keys(pages).some((pid) => taken(pid) < 3) && shots().length < 60) await playOne(pages, latest, shots);
      expect(room().status).toBe('playing');
      const loser = pages[latest().turn]!;
      await loser.getByRole('button', { name: 'Concede' }).click();
      await loser.getByRole('button', { name: 'Really concede? Click again' }).click();
      await expect.poll(() => room().status, { timeout: 10_000 }).toBe('over');
      expect(room().rated).not.toBe(false);
      const stored = async (pid: string) => {
        const res = await fetch(`${server.url}/api/players/${encodeURIComponent(pid)}`);
        return Math.round(((await res.json()) as { ratings: Record<string, { rating: number }> }).ratings.nineball!.rating);
      };
      const players = room().players;
      const after = await Promise.all(players.map((p) => stored(p.id)));
      const winner = players.findIndex((p) => p.id === room().winner);
      for (const p of [a, b]) {
        const rating = p.getByRole('dialog').getByRole('list', { name: 'Rating' });
        await expect.poll(() => rating.locator('li').allTextContents(), { timeout: 15_000 }).toEqual(
          players.map((pl, i) => expect.stringMatching(new RegExp(`^${pl.name}: 1500 → ${after[i]} \\(${i === winner ? '\\+' : '−'}\\d+\\)$`))),
        );
      }
    } finally {
      await watcher.close(200);
      await a.context().close();
      await b.context().close();
    }
  }, 240_000);
});
