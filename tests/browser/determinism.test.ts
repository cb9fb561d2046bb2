// The golden corpus gives the same hashes in Node, in Chromium and in Firefox: server and client
// compute the same bits.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Browser } from 'playwright-core';
import { chromiumAvailable, launchChromium } from '../support/browser.ts';
import { corpusHashes } from '../support/corpus-hashes.ts';
import { serveCorpusPage, type CorpusPage } from '../support/corpus-page.ts';
import { firefoxAvailable, launchFirefox } from '../support/firefox.ts';

const node = corpusHashes();

describe.skipIf(!chromiumAvailable())('the golden corpus in Chromium', () => {
  let browser: Browser;
  let page: CorpusPage;
  beforeAll(async () => {
    page = await serveCorpusPage();
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await page?.close();
  });

  it('gives the same hash for every case as Node', async () => {
    const tab = await browser.newPage();
    await tab.goto(page.url);
    const hashes = await tab.waitForFunction(() => (window as unknown as { baizeCorpusHashes?: Record<string, string> }).baizeCorpusHashes, undefined, { timeout: 60_000 });
    const inBrowser = (await hashes.jsonValue()) as Record<string, string>;
    expect(Object.keys(inBrowser).length).toBe(Object.keys(node).length);
    expect(inBrowser).toEqual(node);
  });
});

describe.skipIf(!firefoxAvailable())('the golden corpus in Firefox', () => {
  it('gives the same hash for every case as Node, reported back to a local server', async () => {
    const page = await serveCorpusPage();
    const firefox = launchFirefox(`${page.url}?report=${encodeURIComponent(page.reportUrl)}`);
    const exited = new Promise<never>((_, reject) => firefox.once('exit', (code) => reject(new Error(`firefox exited with ${code} before reporting`))));
    try {
      const report = await Promise.race([page.report, exited]);
      expect(report.userAgent).toMatch(/Firefox\//);
      expect(report.hashes).toEqual(node);
    } finally {
      firefox.kill('SIGKILL');
      await page.close();
    }
  }, 120_000);
});
