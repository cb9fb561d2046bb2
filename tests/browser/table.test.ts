// The table as drawn, in Chromium: a practice break that pots balls shows them in the "Pocketed"
// tray by id, in the order they went down, once they have dropped; the page's hash is the local
// simulation's before and after the animation; undo puts them back on the table and out of the tray.
// In a room, a spectator's tray is the server's game (the rack's balls off the table), also after a
// reload.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { POOL_OBJECT_BALLS } from '../../shared/rules/index.ts';
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
});
