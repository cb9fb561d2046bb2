// Defect 7 of issue 37: a room on a phone. Held sideways (844x390 CSS px) the table takes at least
// 70% of the width and "Shoot" is on screen; held upright (390x844) the balls are drawn big enough
// for their numbers to be read (the canvas says its ball radius in CSS px: data-ball-radius).
import type { Browser, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
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
});
