// The table as drawn, in Chromium: a practice break that pots balls shows them in the "Pocketed"
// tray by id, in the order they went down, once they have dropped; the page's hash is the local
// simulation's before and after the animation; undo puts them back on the table and out of the tray.
// In a room, a spectator's tray is the server's game (the rack's balls off the table), also after a
// reload.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { cueBallId, newGame, playShot, POOL_OBJECT_BALLS } from '../../shared/rules/index.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';
import { ask, connect, playTurn, until, wsUrl } from '../support/game-clients.ts';

const hashOf = (page: Page) => page.locator('canvas.table').getAttribute('data-outcome-hash');
const trayIds = (page: Page) =>
  page.getByRole('list', { name: 'Pocketed' }).getByRole('listitem').evaluateAll((els) => els.map((e) => `${e.getAttribute('data-ball')}=${e.getAttribute('aria-label')}`));

/**
 * The practice page's first table (nine-ball, seed 1) and a break the keys can aim exactly: power
 * up 30 presses (10 m/s), the heading turned by `turns` presses of 0.008 rad, as aim.ts does. The
 * first such break that pots two or more object balls and not the cue ball.
 */
function pottingBreak(): { presses: string[]; hash: string; pots: string[] } {
  const g = newGame('practice', ['me'], { layout: 'nineball' });
  let speed = 2.5;
  for (let i = 0; i < 30; i++) speed = Math.min(10, speed + 0.25);
  for (let k = 0; k <= 40; k++) {
    for (const [key, sign] of [['ArrowLeft', 1], ['ArrowRight', -1]] as const) {
      let heading = 0;
      for (let i = 0; i < k; i++) heading += sign * 0.008;
      const played = playShot(g, { ball: cueBallId(g), heading, speed, side: 0, top: 0, player: 'me' });
      const pots = played.outcome.events.filter((e) => e.kind === 'pocket').map((e) => e.balls[0]!);
      if (pots.length >= 2 && !pots.includes('cue')) {
        return { presses: [...Array<string>(30).fill('ArrowUp'), ...Array<string>(k).fill(key)], hash: played.outcome.hash, pots };
      }
    }
  }
  throw new Error('no potting break found');
}

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
});
