// A table in Chromium as a player uses it: a waiting table shows its invite link and can be
// closed; a click holds the aim while the mouse goes to "Shoot"; after a shot the opponent's
// clock counts from when the balls stop; a conceded match says so once, in a result dialog with
// "Rematch" and "Lobby", and its replay lists it; a chat flood is told to its sender; an unknown
// room has no chat.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import type { ServerMessage } from '../../shared/protocol/index.ts';
import { cueBallId, newGame } from '../../shared/rules/index.ts';
import { fullPull, pullToSpeed } from '../../client/table/cue.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';
import { tableOnScreen } from '../support/table-screen.ts';

describe.skipIf(!chromiumAvailable())('a table in Chromium', () => {
  const env = serverAndChromium();

  async function player(): Promise<Page> {
    const ctx = await env.browser.newContext({ viewport: { width: 1100, height: 900 } });
    const page = await ctx.newPage();
    await page.goto(`${env.server.url}/`);
    await page.waitForSelector('#server-status.ok');
    return page;
  }

  async function openTable(page: Page, shotClock = 0): Promise<string> {
    if (shotClock > 0) await page.getByLabel('Shot clock (s)').fill(String(shotClock));
    await page.getByRole('button', { name: 'Create table' }).click();
    await page.waitForURL(/\/room\/[\w-]+$/);
    return page.url().split('/').at(-1)!;
  }

  /** A table opened by one player (a, who breaks) and joined by another (b) through its link. */
  async function twoPlayers(shotClock = 0): Promise<{ a: Page; b: Page; id: string }> {
    const a = await player();
    const id = await openTable(a, shotClock);
    const b = await player();
    await b.goto(`${env.server.url}/room/${id}`);
    await b.getByRole('button', { name: 'Join' }).click();
    return { a, b, id };
  }

  it('shows a waiting table\'s invite link, and its player can close it', async () => {
    const a = await player();
    const id = await openTable(a);
    await expect.poll(() => a.getByRole('link', { name: 'Invite link' }).getAttribute('href')).toBe(`${env.server.url}/room/${id}`);
    const b = await player();
    await expect.poll(() => b.locator(`li[data-room="${id}"]`).count()).toBe(1);
    await a.getByRole('button', { name: 'Close table' }).click();
    await a.waitForURL(`${env.server.url}/`);
    await expect.poll(() => a.locator(`li[data-room="${id}"]`).count()).toBe(0);
    // Lobby updates are coalesced, one a second at most: b's comes within about 1.25 s.
    await expect.poll(() => b.locator(`li[data-room="${id}"]`).count(), { timeout: 5000 }).toBe(0);
    await a.context().close();
    await b.context().close();
  });

  it('labels the player\'s own table "Open" in the lobby', async () => {
    const a = await player();
    const id = await openTable(a);
    await a.goto(`${env.server.url}/`);
    await expect.poll(() => a.locator(`li[data-room="${id}"] a`).textContent()).toBe('Open');
    const b = await player();
    await expect.poll(() => b.locator(`li[data-room="${id}"] a`).textContent()).toBe('Join');
    await a.context().close();
    await b.context().close();
  });

  it('holds the aim after a click while the mouse goes to "Shoot"', async () => {
    const page = await player();
    await page.goto(`${env.server.url}/practice`);
    const canvas = page.locator('canvas.table');
    const aimShown = page.getByLabel('Aim', { exact: true });
    const box = (await canvas.boundingBox())!;
    const at = (fx: number, fy: number) => ({ x: box.x + box.width * fx, y: box.y + box.height * fy });
    // Hovering aims.
    const p1 = at(0.8, 0.3);
    await page.mouse.move(p1.x, p1.y);
    const first = await aimShown.textContent();
    const p2 = at(0.2, 0.8);
    await page.mouse.move(p2.x, p2.y, { steps: 5 });
    const second = await aimShown.textContent();
    expect(second).not.toBe(first);
    // A click holds it: moving across the table to the button leaves it where it was.
    await page.mouse.click(p1.x, p1.y);
    const held = await aimShown.textContent();
    const shoot = (await page.getByRole('button', { name: 'Shoot' }).boundingBox())!;
    await page.mouse.move(p2.x, p2.y, { steps: 5 });
    await page.mouse.move(shoot.x + shoot.width / 2, shoot.y + shoot.height / 2, { steps: 5 });
    expect(await aimShown.textContent()).toBe(held);
    // Pressing and dragging aims again.
    await page.mouse.move(p2.x, p2.y);
    await page.mouse.down();
    await page.mouse.move(p2.x + 5, p2.y - 40, { steps: 5 });
    await page.mouse.up();
    expect(await aimShown.textContent()).not.toBe(held);
    await page.context().close();
  });

  it('after a shot, shows the opponent the whole clock until the balls stop; a spectator has no cue', async () => {
    const { a, b, id } = await twoPlayers(30);
    const shoot = a.getByRole('button', { name: 'Shoot' });
    await expect.poll(() => shoot.isEnabled(), { timeout: 10_000 }).toBe(true);
    await shoot.click();
    // While the break's balls roll, the clock shows more than the 30 s it will count from their stop.
    const clock = b.getByRole('timer', { name: 'Shot clock' });
    // It shows the full 30 s until the balls stop, then counts down.
    await expect.poll(async () => Number((await clock.textContent())?.replace(' s', '')), { timeout: 5_000 }).toBe(30);
    await expect.poll(async () => Number((await clock.textContent())?.replace(' s', '')), { timeout: 20_000 }).toBeLessThan(30);
    // Someone watching the game in play has no cue.
    const c = await player();
    await c.goto(`${env.server.url}/room/${id}`);
    await c.waitForSelector('canvas.table');
    expect(await c.getByRole('button', { name: 'Shoot' }).isVisible()).toBe(false);
    expect(await c.getByLabel('Power', { exact: true }).isVisible()).toBe(false);
    await a.context().close();
    await b.context().close();
    await c.context().close();
  });

  it('ends a conceded match with one sentence, and its replay lists the concession', async () => {
    const { a, b, id } = await twoPlayers();
    const shoot = a.getByRole('button', { name: 'Shoot' });
    await expect.poll(() => shoot.isEnabled(), { timeout: 10_000 }).toBe(true);
    // The player not on turn has no stroke controls on screen (hidden, not only disabled).
    await expect.poll(() => b.getByRole('button', { name: 'Concede' }).isVisible(), { timeout: 10_000 }).toBe(true);
    expect(await b.getByRole('button', { name: 'Shoot' }).isVisible()).toBe(false);
    expect(await b.getByLabel('Power', { exact: true }).isVisible()).toBe(false);
    await shoot.click();
    await expect.poll(() => b.getByRole('button', { name: 'Concede' }).isVisible(), { timeout: 10_000 }).toBe(true);
    // One click asks again; only the second concedes.
    await b.getByRole('button', { name: 'Concede' }).click();
    await b.waitForTimeout(300);
    expect(await b.getByRole('status', { name: 'Referee' }).textContent()).not.toMatch(/concedes/);
    await b.getByRole('button', { name: 'Really concede? Click again' }).click();
    const said = a.getByRole('status', { name: 'Referee' });
    // (One shot each at most: the match does not count for the ratings, and the page says so.)
    await expect.poll(() => said.textContent(), { timeout: 10_000 }).toMatch(/concedes; .+ wins\. Not rated: each player must take at least 3 shots\.$/);
    expect((await said.textContent())!.match(/wins/g)).toHaveLength(1);
    // The result dialog, named by its heading, with the score, why it is not rated, and no cue left on screen.
    const dialog = a.getByRole('dialog', { name: 'You win' });
    await expect.poll(() => dialog.isVisible(), { timeout: 10_000 }).toBe(true);
    expect(await dialog.textContent()).toMatch(/ 0 – 0 .+ \(racks\)Not rated: each player must take at least 3 shots\./);
    await expect.poll(() => b.getByRole('dialog', { name: / wins$/ }).isVisible(), { timeout: 10_000 }).toBe(true);
    for (const page of [a, b]) expect(await page.getByRole('button', { name: 'Shoot' }).isVisible()).toBe(false);
    // A rematch asked for by one is shown to the other.
    await b.getByRole('dialog').getByRole('button', { name: 'Rematch' }).click();
    await expect.poll(() => a.getByText(/asks for a rematch\.$/).count()).toBe(1);
    await expect.poll(() => b.getByRole('button', { name: 'Rematch' }).getAttribute('aria-pressed')).toBe('true');
    // "Lobby" goes back to the lobby.
    await b.getByRole('dialog').getByRole('button', { name: 'Lobby' }).click();
    await b.waitForURL(`${env.server.url}/`);
    const { matches } = (await (await fetch(`${env.server.url}/api/matches?limit=1`)).json()) as { matches: { id: number }[] };
    await a.goto(`${env.server.url}/match/${matches[0]!.id}`);
    const shots = a.getByRole('list', { name: 'Shots' }).getByRole('listitem');
    await expect.poll(() => shots.count(), { timeout: 10_000 }).toBe(2);
    expect(await shots.nth(1).textContent()).toMatch(/ conceded$/);
    await a.context().close();
    await b.context().close();
  });

  it('a shot the server refuses says why, and the player may shoot again', async () => {
    const { a, b } = await twoPlayers();
    const shoot = a.getByRole('button', { name: 'Shoot' });
    await expect.poll(() => shoot.isEnabled(), { timeout: 10_000 }).toBe(true);
    // The shot leaves for a state the server does not hold: it refuses it.
    await a.evaluate(() => {
      const send = WebSocket.prototype.send;
      WebSocket.prototype.send = function (this: WebSocket, data: string) {
        const m = JSON.parse(data) as { type: string; stateId?: number };
        if (m.type === 'shot') m.stateId = (m.stateId ?? 0) + 5;
        send.call(this, JSON.stringify(m));
      } as typeof send;
    });
    await shoot.click();
    const said = a.getByRole('status', { name: 'Referee' });
    await expect.poll(() => said.textContent(), { timeout: 20_000 }).toMatch(/^The server refused the shot: ./);
    // Still said once the page has settled, and the same player may shoot again.
    await a.waitForTimeout(500);
    expect(await said.textContent()).toMatch(/^The server refused the shot: ./);
    await expect.poll(() => shoot.isEnabled(), { timeout: 10_000 }).toBe(true);
    await a.context().close();
    await b.context().close();
  });

  it('says a chat line refused as too fast to its sender, by the chat box', async () => {
    const { a, b } = await twoPlayers();
    const text = a.getByRole('textbox', { name: 'Message' });
    await expect.poll(() => text.isVisible(), { timeout: 10_000 }).toBe(true);
    for (let i = 0; i < 8; i++) {
      await text.fill(`line ${i}`);
      await text.press('Enter');
    }
    await expect.poll(() => a.getByRole('status').filter({ hasText: /^You are sending messages too fast; wait \d+ s\.$/ }).count(), { timeout: 10_000 }).toBe(1);
    // Only the lines let through reach the other player.
    await expect.poll(() => b.getByRole('list', { name: 'Chat' }).getByRole('listitem').count(), { timeout: 10_000 }).toBe(5);
    await a.context().close();
    await b.context().close();
  });

  it('an unknown room says so, with a link to the lobby and no chat', async () => {
    const a = await player();
    await a.goto(`${env.server.url}/room/no-such-room`);
    await expect.poll(() => a.getByRole('heading', { name: 'No such room' }).count(), { timeout: 10_000 }).toBe(1);
    expect(await a.getByRole('link', { name: 'Back to the lobby' }).getAttribute('href')).toBe('/');
    expect(await a.getByRole('textbox', { name: 'Message' }).count()).toBe(0);
    expect(await a.getByRole('button', { name: 'Send' }).count()).toBe(0);
    await a.context().close();
  });

  it('keeps a race the player typed across a change of game, and takes the default for an empty one', async () => {
    const a = await player();
    const race = a.getByLabel('Race to');
    await a.getByLabel('Game').selectOption('threecushion');
    expect(await race.inputValue()).toBe('15');
    await race.fill('3');
    await a.getByLabel('Game').selectOption('nineball');
    expect(await race.inputValue()).toBe('3');
    await race.fill('');
    await a.getByRole('button', { name: 'Create table' }).click();
    await a.waitForURL(/\/room\/[\w-]+$/);
    await expect.poll(() => a.getByRole('heading', { level: 2 }).textContent()).toBe('Nine-ball, race to 1');
    // Someone else watching the table has no cue.
    const c = await player();
    await c.goto(a.url());
    await expect.poll(() => c.getByText('Waiting for an opponent.').count()).toBe(1);
    expect(await c.getByRole('button', { name: 'Shoot' }).count()).toBe(0);
    await a.context().close();
    await c.context().close();
  });

  it('practice: a ball being placed follows the pointer, and a refused spot says why and puts it back', async () => {
    const page = await player();
    await page.goto(`${env.server.url}/practice`);
    await page.getByLabel('Place balls').check();
    const g = newGame('practice', ['me'], { layout: 'nineball' });
    const { at: toScreen } = await tableOnScreen(page, g.table);
    /** The canvas's colour under a point of the page. */
    const pixel = (p: { x: number; y: number }) => page.evaluate(({ x, y }) => {
      const c = document.querySelector('canvas.table') as HTMLCanvasElement;
      const r = c.getBoundingClientRect();
      const dpr = c.width / r.width;
      return [...c.getContext('2d')!.getImageData(Math.round((x - r.left) * dpr), Math.round((y - r.top) * dpr), 1, 1).data];
    }, p);
    const cue = g.balls.find((b) => b.id === 'cue')!;
    const open = toScreen({ x: -0.3, y: 0.3 });
    const cloth = await pixel(open);
    const from = toScreen(cue);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(open.x, open.y, { steps: 5 });
    const [r, gr, b] = await pixel(open);
    expect(Math.min(r!, gr!, b!)).toBeGreaterThan(200); // the white cue ball under the pointer
    // Let go on the rack's front ball: refused, said plainly, and the ball goes back.
    const apex = toScreen(g.balls.find((x) => x.id === '1')!);
    await page.mouse.move(apex.x, apex.y, { steps: 5 });
    await page.mouse.up();
    await expect.poll(() => page.locator('.verdict').textContent()).toBe('The cue ball cannot go there: it must lie on the cloth, clear of the other balls.');
    expect(await pixel(open)).toEqual(cloth);
    await page.context().close();
  });

  it('plays a drag pulled back from the cue ball with the drag\'s power, broadcast and hash-equal; a watcher fast-forwards it to the same end', async () => {
    const { a, b, id } = await twoPlayers();
    const watcher = await ProtocolClient.connect(`${env.server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello', name: 'Watch-drag' });
    const shots: Extract<ServerMessage, { type: 'shot' }>[] = [];
    const arrived: number[] = [];
    watcher.onMessage((m) => {
      if (m.type !== 'shot') return;
      shots.push(m);
      arrived.push(Date.now());
    });
    await watcher.request({ type: 'watch', room: id });
    await expect.poll(() => a.getByRole('button', { name: 'Shoot' }).isEnabled(), { timeout: 10_000 }).toBe(true);
    // The break: the cue ball in hand in the kitchen, aimed up the table (heading 0) at the rack.
    const g = newGame('nineball', ['x', 'y']);
    const cue = g.balls.find((x) => x.id === cueBallId(g))!;
    const { scale, at } = await tableOnScreen(a, g.table);
    const from = at(cue);
    const aimShown = a.getByLabel('Aim', { exact: true });
    const aimed = await aimShown.textContent();
    // Pulled back less than the cancel distance and let go: nothing is played, the aim holds.
    await a.mouse.move(from.x, from.y);
    await a.mouse.down();
    await a.mouse.move(from.x - 8, from.y, { steps: 4 });
    await a.mouse.up();
    await a.waitForTimeout(500);
    expect(shots).toHaveLength(0);
    // Pulled back 120 px, a little off the line (only the pull along it counts), and let go: played.
    await a.mouse.move(from.x, from.y);
    await a.mouse.down();
    await a.mouse.move(from.x - 60, from.y + 10, { steps: 4 });
    // While pulling, the power meter reads the pull.
    expect(await a.getByLabel('Power', { exact: true }).inputValue()).toBe(String(pullToSpeed(60 / scale, 0, fullPull(scale))));
    await a.mouse.move(from.x - 120, from.y + 15, { steps: 4 });
    await a.mouse.up();
    await expect.poll(() => shots.length, { timeout: 10_000 }).toBe(1);
    const shot = shots[0]!;
    expect(shot.shot.speed).toBeCloseTo(pullToSpeed(120 / scale, 0, fullPull(scale))!, 1);
    expect(shot.shot.speed).toBeGreaterThan(6);
    expect(shot.shot.heading).toBe(0); // the drag did not turn the cue
    expect(shot.cueBall).toBeUndefined(); // nor move the ball in hand
    expect(await aimShown.textContent()).toBe(aimed);
    const hashOf = (p: Page) => p.locator('canvas.table').getAttribute('data-outcome-hash');
    await expect.poll(() => hashOf(a)).toBe(shot.outcome.hash);
    await expect.poll(() => hashOf(b)).toBe(shot.outcome.hash);
    // The opponent watches it at x2, x4, then skips to its end: the same end, long before its time.
    const ff = b.getByRole('button', { name: 'Fast forward' });
    await expect.poll(() => ff.isVisible(), { timeout: 5_000 }).toBe(true);
    expect(await ff.textContent()).toBe('Fast forward ×2');
    await ff.click();
    expect(await ff.textContent()).toBe('Fast forward ×4');
    await b.keyboard.press('f');
    expect(await ff.textContent()).toBe('Fast forward to the end');
    await ff.click();
    await expect.poll(() => ff.isVisible(), { timeout: 2_000 }).toBe(false);
    expect(Date.now() - arrived[0]!).toBeLessThan(shot.outcome.duration * 1000);
    expect(await hashOf(b)).toBe(shot.outcome.hash);
    expect(await b.evaluate(() => (window as unknown as { baizeMismatches: { mismatches: number } }).baizeMismatches.mismatches)).toBe(0);
    // The shooter's own page lets it play out; its button goes once the balls stop.
    await expect.poll(() => a.getByRole('button', { name: 'Fast forward' }).isVisible(), { timeout: 30_000 }).toBe(false);
    await watcher.close();
    await a.context().close();
    await b.context().close();
  }, 60_000);

  it('practice: a drag pulled back from the cue ball plays at its power without turning the cue; pulled forward, it cancels', async () => {
    const page = await player();
    await page.goto(`${env.server.url}/practice`);
    const g = newGame('practice', ['me'], { layout: 'nineball' });
    const { scale, at } = await tableOnScreen(page, g.table);
    const from = at(g.balls.find((x) => x.id === 'cue')!);
    // Aim at the rack and hold it with a click; then the pointer goes to the cue ball.
    const rack = g.balls.find((x) => x.id === '1')!;
    await page.mouse.click(at(rack).x, at(rack).y);
    const aimShown = page.getByLabel('Aim', { exact: true });
    const aimed = await aimShown.textContent();
    const power = page.getByLabel('Power', { exact: true });
    const before = await power.inputValue();
    // Pulled forward (towards the aim) and let go: nothing played, the power as it was.
    await page.mouse.move(from.x, from.y, { steps: 3 });
    await page.mouse.down();
    await page.mouse.move(from.x + 80, from.y, { steps: 4 });
    await page.mouse.up();
    await page.waitForTimeout(300);
    expect(await page.locator('canvas.table').getAttribute('data-outcome-hash')).toBeNull();
    expect(await power.inputValue()).toBe(before);
    // Pulled back 50 px: played at that power.
    await page.mouse.move(from.x, from.y, { steps: 3 });
    await page.mouse.down();
    await page.mouse.move(from.x - 50, from.y, { steps: 4 });
    await page.mouse.up();
    await expect.poll(() => page.locator('canvas.table').getAttribute('data-outcome-hash')).not.toBeNull();
    expect(Number(await power.inputValue())).toBeCloseTo(pullToSpeed(50 / scale, 0, fullPull(scale))!, 1);
    expect(await aimShown.textContent()).toBe(aimed);
    await expect.poll(() => page.getByRole('button', { name: 'Fast forward' }).isVisible()).toBe(true);
    await page.context().close();
  });

  it('practice: a touch pulled back from the cue ball plays too', async () => {
    const ctx = await env.browser.newContext({ viewport: { width: 844, height: 390 }, hasTouch: true });
    const page = await ctx.newPage();
    await page.goto(`${env.server.url}/practice`);
    const g = newGame('practice', ['me'], { layout: 'nineball' });
    const { scale, at } = await tableOnScreen(page, g.table);
    const from = at(g.balls.find((x) => x.id === 'cue')!);
    const cdp = await ctx.newCDPSession(page);
    const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', x = 0, y = 0) =>
      cdp.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y }] });
    await touch('touchStart', from.x, from.y);
    for (let i = 1; i <= 6; i++) await touch('touchMove', from.x - 10 * i, from.y);
    await touch('touchEnd');
    await expect.poll(() => page.locator('canvas.table').getAttribute('data-outcome-hash')).not.toBeNull();
    expect(Number(await page.getByLabel('Power', { exact: true }).inputValue())).toBeCloseTo(pullToSpeed(60 / scale, 0, fullPull(scale))!, 1);
    expect(await page.getByLabel('Aim', { exact: true }).textContent()).toBe('0.00°');
    await ctx.close();
  });

  it('turns the sound off and on with "Sound", remembered after a reload', async () => {
    const page = await player();
    await page.goto(`${env.server.url}/practice`);
    const sound = page.getByRole('button', { name: 'Sound', exact: true });
    expect(await sound.getAttribute('aria-pressed')).toBe('true');
    await sound.click();
    expect(await sound.getAttribute('aria-pressed')).toBe('false');
    await page.reload();
    expect(await page.getByRole('button', { name: 'Sound', exact: true }).getAttribute('aria-pressed')).toBe('false');
    // The room has it too, and the same choice.
    await page.goto(`${env.server.url}/`);
    const id = await openTable(page);
    const inRoom = page.getByRole('button', { name: 'Sound', exact: true });
    expect(await inRoom.getAttribute('aria-pressed')).toBe('false');
    await inRoom.click();
    expect(await inRoom.getAttribute('aria-pressed')).toBe('true');
    await page.goto(`${env.server.url}/room/${id}`);
    expect(await page.getByRole('button', { name: 'Sound', exact: true }).getAttribute('aria-pressed')).toBe('true');
    await page.context().close();
  });

  it('places a ball in hand from the keyboard: Alt and the arrows, 1 cm a press', async () => {
    const { a, b, id } = await twoPlayers();
    const watcher = await ProtocolClient.connect(`${env.server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello', name: 'Watch-keys' });
    const shots: Extract<ServerMessage, { type: 'shot' }>[] = [];
    watcher.onMessage((m) => m.type === 'shot' && shots.push(m));
    await watcher.request({ type: 'watch', room: id });
    // The breaker strokes away from the rack as softly as the keys allow: a foul, ball in hand.
    const shootA = a.getByRole('button', { name: 'Shoot' });
    await expect.poll(() => shootA.isEnabled(), { timeout: 10_000 }).toBe(true);
    const canvasA = a.locator('canvas.table');
    await canvasA.focus();
    for (let i = 0; i < 12; i++) await canvasA.press('ArrowDown');
    for (let i = 0; i < 390; i++) await canvasA.press('ArrowLeft');
    await canvasA.press('Space');
    await expect.poll(() => shots.length, { timeout: 10_000 }).toBe(1);
    const g = shots[0]!.game;
    expect(g.ballInHand).toBe('anywhere');
    const cue = g.balls.find((x) => x.id === cueBallId(g))!;
    const shootB = b.getByRole('button', { name: 'Shoot' });
    await expect.poll(() => shootB.isEnabled(), { timeout: 30_000 }).toBe(true);
    const canvasB = b.locator('canvas.table');
    await canvasB.focus();
    for (let i = 0; i < 5; i++) await canvasB.press('Alt+ArrowUp');
    await canvasB.press('Alt+Shift+ArrowRight');
    await shootB.click();
    await expect.poll(() => shots.length, { timeout: 10_000 }).toBe(2);
    const placed = shots[1]!.cueBall!;
    expect(placed.x).toBeCloseTo(cue.x + 0.001, 6);
    expect(placed.y).toBeCloseTo(cue.y + 0.05, 6);
    await watcher.close();
    await a.context().close();
    await b.context().close();
  });
});
