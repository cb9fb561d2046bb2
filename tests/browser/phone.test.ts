// Defect 7 of issue 37: a room on a phone. Held sideways (844x390 CSS px) the table takes at least
// 70% of the width and "Shoot" is on screen; held upright (390x844) the balls are drawn big enough
// for their numbers to be read (the canvas says its ball radius in CSS px: data-ball-radius), the
// numbers read upright on the screen though the table is turned, and Alt + an arrow moves a ball
// in hand the way the arrow points on the screen.
import type { Browser, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import { RAIL } from '../../client/table/draw.ts';
import { tableSpec } from '../../shared/physics/index.ts';
import type { ServerMessage } from '../../shared/protocol/index.ts';
import { poolMarks } from '../../shared/rules/index.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';

/** Smallest ball radius (CSS px) at which a ball's number can be read. */
const READABLE_RADIUS = 7;

async function phone(browser: Browser, url: string, width: number, height: number): Promise<Page> {
  const ctx = await browser.newContext({ viewport: { width, height }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  const page = await ctx.newPage();
  await page.goto(url);
  await page.waitForSelector('#server-status.ok');
  return page;
}

describe.skipIf(!chromiumAvailable())('a room on a phone in Chromium', () => {
  const env = serverAndChromium();

  /** A nine-ball table opened by a (who breaks) and joined by b, each on a phone of the given size. */
  async function table(width: number, height: number, kind = 'nineball'): Promise<{ a: Page; b: Page }> {
    const a = await phone(env.browser, `${env.server.url}/`, width, height);
    await a.getByLabel('Game').selectOption(kind);
    await a.getByRole('button', { name: 'Create table' }).click();
    await a.waitForURL(/\/room\/[\w-]+$/);
    const b = await phone(env.browser, a.url(), width, height);
    await b.getByRole('button', { name: 'Join' }).click();
    await a.getByRole('button', { name: 'Shoot' }).waitFor();
    await expect.poll(() => a.getByRole('button', { name: 'Shoot' }).isEnabled()).toBe(true);
    return { a, b };
  }

  it.each(['nineball', 'snooker'])('sideways (844x390), %s: the table is at least 70 percent of the width and "Shoot" is on screen', async (kind) => {
    const { a, b } = await table(844, 390, kind);
    const canvas = a.locator('canvas.table');
    const box = (await canvas.boundingBox())!;
    const shoot = (await a.getByRole('button', { name: 'Shoot' }).boundingBox())!;
    console.log(`phone sideways (${kind}): table ${box.width.toFixed(0)}x${box.height.toFixed(0)} at (${box.x.toFixed(0)}, ${box.y.toFixed(0)}); Shoot at (${shoot.x.toFixed(0)}, ${shoot.y.toFixed(0)}) ${shoot.width.toFixed(0)}x${shoot.height.toFixed(0)}`);
    if (kind === 'nineball') await a.screenshot({ path: '/tmp/phone-sideways.png' });
    expect(box.width).toBeGreaterThanOrEqual(0.7 * 844);
    // The whole table and "Shoot" on the screen as the page opens, without scrolling.
    expect(box.y).toBeGreaterThanOrEqual(0);
    expect(box.y + box.height).toBeLessThanOrEqual(390);
    expect(shoot.x).toBeGreaterThanOrEqual(0);
    expect(shoot.y).toBeGreaterThanOrEqual(0);
    expect(shoot.x + shoot.width).toBeLessThanOrEqual(844);
    expect(shoot.y + shoot.height).toBeLessThanOrEqual(390);
    // And it plays: a tap on "Shoot" strikes.
    await a.getByRole('button', { name: 'Shoot' }).tap();
    await expect.poll(() => b.locator('canvas.table').getAttribute('data-outcome-hash'), { timeout: 20_000 }).toMatch(/^[0-9a-f]{16,}$/);
    await a.context().close();
    await b.context().close();
  }, 60_000);

  it.each(['nineball', 'eightball'])('upright (390x844), %s: the numbered balls are drawn at a readable size (snooker has no numbers)', async (kind) => {
    const { a, b } = await table(390, 844, kind);
    const canvas = a.locator('canvas.table');
    const radius = Number(await canvas.getAttribute('data-ball-radius'));
    const box = (await canvas.boundingBox())!;
    console.log(`phone upright (${kind}): table ${box.width.toFixed(0)}x${box.height.toFixed(0)}, ball radius ${radius} CSS px`);
    if (kind === 'nineball') await a.screenshot({ path: '/tmp/phone-upright.png' });
    expect(radius).toBeGreaterThanOrEqual(READABLE_RADIUS);
    expect(box.x).toBeGreaterThanOrEqual(0);
    expect(box.x + box.width).toBeLessThanOrEqual(390);
    // Turned, a touch still aims where it is: straight up the screen from the cue ball is +x
    // (heading 0°), a touch up and to its right is between +x and -y.
    const aimAt = async (fx: number, fy: number): Promise<number> => {
      await canvas.scrollIntoViewIfNeeded();
      const b = (await canvas.boundingBox())!;
      await a.touchscreen.tap(b.x + b.width * fx, b.y + b.height * fy);
      const text = (await a.locator('.controls').textContent())!;
      const deg = Number(/Aim (-?[\d.]+)°/.exec(text)![1]);
      return ((deg + 540) % 360) - 180; // in (-180, 180]
    };
    expect(Math.abs(await aimAt(0.5, 0.2))).toBeLessThan(1);
    const right = await aimAt(0.9, 0.75);
    expect(right).toBeLessThan(-10);
    expect(right).toBeGreaterThan(-90);
    await a.context().close();
    await b.context().close();
  }, 60_000);
  it('upright (390x844): a ball\'s number reads upright on the screen, and Alt + arrows move the ball in hand as the arrows point', async () => {
    const { a, b } = await table(390, 844);
    const id = /\/room\/([\w-]+)$/.exec(a.url())![1]!;
    // The 1 stands on the foot spot, at rest (not turned). On the page not on turn (no cue
    // drawn over it), the dark ink of its number within half a ball radius of its centre: a "1"
    // read upright is taller than wide on the screen.
    const spec = tableSpec('pool-9ft');
    const canvas = b.locator('canvas.table');
    await canvas.scrollIntoViewIfNeeded();
    const ink = await canvas.evaluate((el, p) => {
      const c = el as HTMLCanvasElement;
      const k = c.width / c.getBoundingClientRect().width;
      const scale = (c.height / k) / p.long; // CSS px a metre, the table's length down the screen
      const cx = c.width / 2;
      const cy = c.height / 2 - p.x * scale * k;
      const r = 0.45 * p.R * scale * k;
      const x0 = Math.floor(cx - r);
      const y0 = Math.floor(cy - r);
      const n = Math.ceil(2 * r);
      const data = c.getContext('2d')!.getImageData(x0, y0, n, n).data;
      let w = 0, mx = 0, my = 0, sxx = 0, syy = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const dx = x0 + i + 0.5 - cx;
          const dy = y0 + j + 0.5 - cy;
          if (dx * dx + dy * dy > r * r) continue;
          const o = 4 * (j * n + i);
          const lum = 0.299 * data[o]! + 0.587 * data[o + 1]! + 0.114 * data[o + 2]!;
          const d = Math.max(0, 140 - lum);
          w += d; mx += d * dx; my += d * dy; sxx += d * dx * dx; syy += d * dy * dy;
        }
      }
      mx /= w; my /= w;
      return { w, wide: Math.sqrt(sxx / w - mx * mx), tall: Math.sqrt(syy / w - my * my) };
    }, { x: poolMarks(spec).footSpot.x, R: spec.ballRadius, long: spec.length + 2 * RAIL });
    console.log(`phone upright: the 1's ink ${ink.wide.toFixed(2)} wide, ${ink.tall.toFixed(2)} tall (device px, standard deviations)`);
    expect(ink.w).toBeGreaterThan(0);
    expect(ink.tall).toBeGreaterThan(1.5 * ink.wide);
    // The 9 (in the middle of the diamond, 2√3 R beyond the 1) has its stripe across the screen,
    // as on a real ball whose number stands upright: ivory above and below its number, yellow beside.
    const blue = await canvas.evaluate((el, p) => {
      const c = el as HTMLCanvasElement;
      const k = c.width / c.getBoundingClientRect().width;
      const scale = ((c.height / k) / p.long) * k;
      const cx = c.width / 2;
      const cy = c.height / 2 - p.x * scale;
      const d = 0.75 * p.R * scale;
      const at = (x: number, y: number) => c.getContext('2d')!.getImageData(Math.round(x), Math.round(y), 1, 1).data[2]!;
      return { above: at(cx, cy - d), below: at(cx, cy + d), left: at(cx - d, cy), right: at(cx + d, cy) };
    }, { x: poolMarks(spec).footSpot.x + 2 * Math.sqrt(3) * spec.ballRadius, R: spec.ballRadius, long: spec.length + 2 * RAIL });
    console.log(`phone upright: the 9's blue channel above ${blue.above}, below ${blue.below}, left ${blue.left}, right ${blue.right}`);
    expect(Math.min(blue.above, blue.below)).toBeGreaterThan(Math.max(blue.left, blue.right) + 60);
    // Up the screen is +x (the table's length), right is -y: 5 cm up and 2 cm right.
    const watcher = await ProtocolClient.connect(`${env.server.url.replace('http', 'ws')}/ws`);
    await watcher.request({ type: 'hello', name: 'Watch-phone' });
    const shots: Extract<ServerMessage, { type: 'shot' }>[] = [];
    watcher.onMessage((m) => m.type === 'shot' && shots.push(m));
    const seen = await watcher.request({ type: 'watch', room: id });
    if (seen.type !== 'room') throw new Error(JSON.stringify(seen));
    const cue = seen.room.game!.balls.find((x) => x.id === 'cue')!;
    const canvasA = a.locator('canvas.table');
    await canvasA.focus();
    for (let i = 0; i < 5; i++) await canvasA.press('Alt+ArrowUp');
    for (let i = 0; i < 2; i++) await canvasA.press('Alt+ArrowRight');
    await a.getByRole('button', { name: 'Shoot' }).tap();
    await expect.poll(() => shots.length, { timeout: 10_000 }).toBe(1);
    const placed = shots[0]!.cueBall!;
    expect(placed.x).toBeCloseTo(cue.x + 0.05, 6);
    expect(placed.y).toBeCloseTo(cue.y - 0.02, 6);
    await watcher.close();
    await a.context().close();
    await b.context().close();
  }, 60_000);
});
