// The table as drawn, in Chromium: a practice break that pots balls shows them in the "Pocketed"
// tray by id, in the order they went down, once they have dropped; the page's hash is the local
// simulation's before and after the animation; undo puts them back on the table and out of the tray.
// In a room, a spectator's tray is the server's game (the rack's balls off the table), also after a
// reload. A replay (/match/<id>) has the same tray: the balls a shot pots show once they have
// dropped, and a jump to a shot shows the tray of the game at that shot.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { cueBallId, playShot, POOL_OBJECT_BALLS, type Game } from '../../shared/rules/index.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';
import { pottingBreak } from '../support/potting-break.ts';
import { ask, connect, playTurn, until, wsUrl } from '../support/game-clients.ts';

const hashOf = (page: Page) => page.locator('canvas.table').getAttribute('data-outcome-hash');
const trayIds = (page: Page) =>
  page.getByRole('list', { name: 'Pocketed' }).getByRole('listitem').evaluateAll((els) => els.map((e) => `${e.getAttribute('data-ball')}=${e.getAttribute('aria-label')}`));


describe.skipIf(!chromiumAvailable())('the table as drawn', () => {
  const env = serverAndChromium();

  it('a pot drops the balls into the "Pocketed" tray by id, in order; the hash stays the simulation\'s', async () => {
    const shot = pottingBreak();
    const ctx = await env.browser.newContext();
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${env.server.url}/practice`);
    await page.waitForSelector('canvas.table');
    const tray = page.getByRole('list', { name: 'Pocketed' });
    await expect.poll(() => tray.isVisible()).toBe(true);
    expect(await trayIds(page)).toEqual([]);
    await page.locator('canvas.table').focus();
    for (const key of shot.presses) await page.keyboard.press(key);
    await page.getByRole('button', { name: 'Shoot' }).click();
    expect(await hashOf(page)).toBe(shot.hash);
    // Nothing is in the tray while the balls still run; then each pocketed ball, in order.
    expect(await trayIds(page)).toEqual([]);
    await expect.poll(() => trayIds(page), { timeout: 30_000 }).toEqual(shot.pots.map((id) => `${id}=${id}`));
    expect(await hashOf(page)).toBe(shot.hash);
    await page.getByRole('button', { name: 'Undo' }).click();
    await expect.poll(() => trayIds(page)).toEqual([]);
    expect(errors).toEqual([]);
    await ctx.close();
  }, 60_000);

  it('a spectator\'s tray lists the balls the server\'s game has pocketed, also after a reload', async () => {
    const url = wsUrl(env.server.url);
    const [a, b] = [await connect(url, { name: 'Tray-A' }), await connect(url, { name: 'Tray-B' })];
    const created = await ask(a, { type: 'create', kind: 'nineball' });
    if (created.type !== 'room') throw new Error(JSON.stringify(created));
    const room = created.room.id;
    await ask(b, { type: 'join', room });
    await until(a, room, (r) => r.status === 'playing');
    const ctx = await env.browser.newContext();
    const page = await ctx.newPage();
    await page.goto(`${env.server.url}/room/${room}`);
    await page.waitForSelector('canvas.table');
    // The sound bots play until a ball is down.
    const down = () => {
      const g = a.rooms.get(room)!.game!;
      return POOL_OBJECT_BALLS.slice(0, 9).filter((id) => !g.balls.some((x) => x.id === id));
    };
    for (let i = 0; i < 12 && down().length === 0 && a.rooms.get(room)!.status === 'playing'; i++) {
      const r = a.rooms.get(room)!;
      const seat = r.game!.turn === a.player.id ? a : b;
      await until(seat, room, (x) => x.stateId === r.stateId);
      await playTurn(seat, room);
      await until(a, room, (x) => x.stateId > r.stateId);
    }
    const expected = down().sort();
    expect(expected.length).toBeGreaterThan(0);
    const shown = async () => (await page.getByRole('list', { name: 'Pocketed' }).getByRole('listitem').evaluateAll((els) => els.map((e) => e.getAttribute('data-ball')!))).sort();
    await expect.poll(shown, { timeout: 60_000 }).toEqual(expected);
    await page.reload();
    await page.waitForSelector('canvas.table');
    await expect.poll(shown, { timeout: 10_000 }).toEqual(expected);
    await ctx.close();
    a.client.close();
    b.client.close();
  }, 120_000);
  it('a replay drops the potted balls into the "Pocketed" tray in order, and a jump shows the tray at that shot', async () => {
    const url = wsUrl(env.server.url);
    const [a, b] = [await connect(url, { name: 'Replay-A' }), await connect(url, { name: 'Replay-B' })];
    const created = await ask(a, { type: 'create', kind: 'nineball' });
    if (created.type !== 'room') throw new Error(JSON.stringify(created));
    const room = created.room.id;
    await ask(b, { type: 'join', room });
    await until(a, room, (r) => r.status === 'playing');
    // A break that pots two or more object balls and not the cue ball, found by trying headings.
    const g = a.rooms.get(room)!.game! as Game;
    const breaker = g.turn === a.player.id ? a : b;
    let stroke: { ball: string; heading: number; speed: number; side: number; top: number } | null = null;
    let pots: string[] = [];
    for (let k = 0; k <= 80 && !stroke; k++) {
      const s = { ball: cueBallId(g), heading: (k % 2 ? -1 : 1) * Math.ceil(k / 2) * 0.004, speed: 10, side: 0, top: 0 };
      const p = playShot(g, { ...s, player: breaker.player.id }).outcome.events.filter((e) => e.kind === 'pocket').map((e) => e.balls[0]!);
      if (p.length >= 2 && !p.includes('cue')) [stroke, pots] = [s, p];
    }
    expect(stroke).not.toBeNull();
    await until(breaker, room, (r) => r.stateId === a.rooms.get(room)!.stateId);
    const shot = await ask(breaker, { type: 'shot', room, stateId: breaker.rooms.get(room)!.stateId, shot: stroke! });
    if (shot.type !== 'shot') throw new Error(JSON.stringify(shot));
    await until(a, room, (r) => r.stateId >= shot.stateId);
    // A second shot, whatever it pots; then a concession ends the match.
    const r = a.rooms.get(room)!;
    const seat = r.game!.turn === a.player.id ? a : b;
    await until(seat, room, (x) => x.stateId === r.stateId);
    await playTurn(seat, room);
    await ask(a, { type: 'concede', room });
    a.client.close();
    b.client.close();
    const { matches } = (await (await fetch(`${env.server.url}/api/matches?limit=1`)).json()) as { matches: { id: number }[] };
    const id = matches[0]!.id;
    const ctx = await env.browser.newContext();
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`${env.server.url}/match/${id}`);
    const tray = page.getByRole('list', { name: 'Pocketed' });
    await expect.poll(() => tray.isVisible(), { timeout: 10_000 }).toBe(true);
    expect(await trayIds(page)).toEqual([]);
    // Played at 4x: nothing in the tray while the break runs, then its pots in order.
    await page.getByLabel('Speed').selectOption('4');
    await page.getByRole('button', { name: 'Play' }).click();
    expect(await trayIds(page)).toEqual([]);
    await expect.poll(() => trayIds(page), { timeout: 30_000 }).toEqual(pots.map((p) => `${p}=${p}`));
    await expect.poll(() => page.getByRole('button', { name: 'Play' }).isVisible(), { timeout: 30_000 }).toBe(true);
    const final = await trayIds(page);
    // Back to the break: the tray of the game before it (empty), then its pots again.
    const links = page.getByRole('list', { name: 'Shots' }).getByRole('link');
    await page.getByLabel('Speed').selectOption('1');
    await links.nth(0).click();
    expect(await trayIds(page)).toEqual([]);
    await expect.poll(() => trayIds(page), { timeout: 30_000 }).toEqual(pots.map((p) => `${p}=${p}`));
    // A shared link to the second shot opens on the tray after the break.
    await page.goto('about:blank');
    await page.goto(`${env.server.url}/match/${id}#shot=2`);
    await expect.poll(() => trayIds(page), { timeout: 10_000 }).toEqual(pots.map((p) => `${p}=${p}`));
    await expect.poll(() => trayIds(page), { timeout: 30_000 }).toEqual(final);
    expect(errors).toEqual([]);
    await ctx.close();
  }, 120_000);
});
