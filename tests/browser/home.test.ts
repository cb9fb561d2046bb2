import { describe, expect, it } from 'vitest';
import type { Browser } from 'playwright-core';
import { simulate } from '../../shared/physics/index.ts';
import { CORPUS } from '../../shared/scenes/index.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';

describe.skipIf(!chromiumAvailable())('the home page in Chromium', () => {
  const env = serverAndChromium();

  it('opens the lobby as a guest at once: a made-up name, the token kept in the browser', async () => {
    const page = await env.browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    page.on('console', (m) => (m.type() === 'error' ? errors.push(m.text()) : undefined));
    await page.goto(`${env.server.url}/`);
    expect(await page.title()).toBe('baize');
    expect(await page.locator('h1').textContent()).toBe('baize');
    const status = page.locator('#server-status');
    await expect.poll(() => status.getAttribute('class')).toBe('ok');
    expect(await status.textContent()).toMatch(/^Playing as Guest-[A-Z2-9]{8}$/);
    expect(await page.evaluate(() => localStorage.getItem('baize.token'))).toMatch(/^[A-Za-z0-9_-]{40,}$/);
    expect(await page.getByRole('button', { name: 'Create table' }).count()).toBe(1);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('replays a corpus shot in the browser with the same hash as the server computes', async () => {
    const page = await env.browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    await page.goto(`${env.server.url}/dev.html`);
    const index = CORPUS.findIndex((c) => c.name === 'snooker black into the corner');
    const c = CORPUS[index]!;
    await page.selectOption('#replay-case', String(index));
    await page.click('#replay-play');
    const info = page.locator('#replay-info');
    await expect.poll(() => info.getAttribute('data-done'), { timeout: 20_000 }).toBe('true');
    expect(await info.getAttribute('data-hash')).toBe(simulate(c.scene, c.shot).hash);
    expect(await info.textContent()).toContain('snooker black into the corner');
    expect(errors).toEqual([]);
    await page.close();
  });
});

