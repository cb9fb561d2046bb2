import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser } from 'playwright-core';
import { simulate } from '../../shared/physics/index.ts';
import { CORPUS } from '../../shared/scenes/index.ts';
import { chromiumAvailable, launchChromium } from '../support/browser.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

describe.skipIf(!chromiumAvailable())('the home page in Chromium', () => {
  let browser: Browser;
  let server: ServerProcess;
  beforeAll(async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db') });
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.stop();
  });

  it('shows the title, the server status from /healthz and a drawn table', async () => {
    const page = await browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    await page.goto(`${server.url}/`);
    expect(await page.title()).toBe('baize');
    expect(await page.locator('h1').textContent()).toBe('baize');
    const status = page.locator('#server-status');
    await expect.poll(() => status.getAttribute('class')).toBe('ok');
    expect(await status.textContent()).toMatch(/^Server online: baize \d+\.\d+\.\d+, schema \d+$/);
    // The canvas holds the cloth's green at its centre: the client bundle ran and drew the table.
    const centre = await page.evaluate(() => {
      const canvas = document.getElementById('table') as HTMLCanvasElement;
      return Array.from(canvas.getContext('2d')!.getImageData(canvas.width / 2, canvas.height / 2, 1, 1).data);
    });
    expect(centre).toEqual([0x1d, 0x7a, 0x45, 255]);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('replays a corpus shot in the browser with the same hash as the server computes', async () => {
    const page = await browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    await page.goto(`${server.url}/`);
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

