// Issue 37 in Chromium: the /help page, and defects 3 (words) and 5 (names of emoji) as a player
// meets them in the pages.
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';

const FAMILY = '\u{1F468}\u200D\u{1F469}\u200D\u{1F467}\u200D\u{1F466}';
const FLAG_SCOTLAND = '\u{1F3F4}\u{E0067}\u{E0062}\u{E0073}\u{E0063}\u{E0074}\u{E007F}';
const EMOJI = [FAMILY, '\u{1F1EB}\u{1F1F7}', FLAG_SCOTLAND, '\u{1F3F3}\uFE0F\u200D\u{1F308}', '\u{1F3B1}'];
const emojiName = (n: number) => Array.from({ length: n }, (_, i) => EMOJI[i % EMOJI.length]).join('');

describe.skipIf(!chromiumAvailable())('help and words in Chromium', () => {
  const env = serverAndChromium();

  async function lobby(): Promise<{ page: Page; errors: string[] }> {
    const ctx = await env.browser.newContext();
    const page = await ctx.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    await page.goto(`${env.server.url}/`);
    await page.waitForSelector('#server-status.ok');
    return { page, errors };
  }

  it('/help answers 200 with a heading per game, the controls and the terms, linked from the lobby', async () => {
    const res = await fetch(`${env.server.url}/help`, { headers: { accept: 'text/html' } });
    expect(res.status).toBe(200);
    const { page, errors } = await lobby();
    await page.getByRole('link', { name: 'How to play' }).click();
    await page.waitForURL(/\/help$/);
    for (const game of ['Nine-ball', 'Eight-ball', 'Snooker', 'Three-cushion', 'Controls']) {
      expect(await page.getByRole('heading', { name: game, exact: true }).count(), game).toBe(1);
    }
    const text = (await page.locator('article.help').textContent())!;
    for (const term of ['Aim to first contact', 'Full cue-ball path', 'No guidance', 'Push-out', 'Ball in hand', 'Shot clock', 'Glicko-2', 'RD', 'provisional', 'Fast forward', 'Sound', 'Alt']) {
      expect(text, term).toContain(term);
    }
    // The header links to it from every page (a room too).
    expect(await page.getByRole('navigation', { name: 'Main' }).getByRole('link', { name: 'Help' }).getAttribute('href')).toBe('/help');
    expect(errors).toEqual([]);
    await page.context().close();
  });

  it('a bad player or match URL says "No such player" / "No such match" in words', async () => {
    const { page } = await lobby();
    for (const [path, words] of [['/player/abc', 'No such player.'], ['/player/424242', 'No such player.'], ['/match/xyz', 'No such match.'], ['/match/424242', 'No such match.']]) {
      await page.goto(`${env.server.url}${path}`);
      await expect.poll(() => page.getByRole('status').filter({ hasText: /such/ }).textContent()).toBe(words);
      expect(await page.locator('#app').textContent()).not.toMatch(/whole number/);
    }
    await page.context().close();
  });

  it('counts in agreement: "1 rated game", "1 game", "1 ranked player"', async () => {
    const { page } = await lobby();
    const json = (body: unknown) => ({ status: 200, contentType: 'application/json', body: JSON.stringify(body) });
    await page.route('**/api/players/7', (r) =>
      r.fulfill(json({ name: 'Solo', games: 1, wins: 1, ratings: { nineball: { rating: 1662, rd: 290, games: 1, wins: 1, provisional: true } }, records: [], recent: [] })),
    );
    await page.route('**/api/leaderboard?*', (r) =>
      r.fulfill(json({ kind: 'nineball', total: 1, entries: [{ rank: 1, player: { id: '7', name: 'Solo' }, rating: 1662, rd: 100, games: 1, wins: 1 }] })),
    );
    await page.goto(`${env.server.url}/player/7`);
    await page.getByRole('heading', { name: 'Solo' }).waitFor();
    const body = (await page.locator('#app').textContent())!;
    expect(body).toContain('1 rated game, 1 won.');
    expect(body).toContain('RD 290), 1 game, 1 won');
    await page.goto(`${env.server.url}/leaderboard`);
    await expect.poll(() => page.locator('#app').textContent()).toContain('1 ranked player:');
    await page.context().close();
  });

  it('a name of emoji is cut whole in the lobby input (never mid-character) and accepted at 32', async () => {
    const { page, errors } = await lobby();
    const input = page.getByRole('textbox', { name: 'Your name' });
    await input.fill(emojiName(40));
    // Never half a character: the first 32 whole ones, and a word on why.
    expect(await input.inputValue()).toBe(emojiName(32));
    expect(await page.getByRole('status').filter({ hasText: 'at most 32 characters' }).count()).toBe(1);
    await page.getByRole('button', { name: 'Change name' }).click();
    await expect.poll(() => page.locator('p.note').textContent()).toBe(`You are ${emojiName(32)}`);
    await expect.poll(() => page.locator('#server-status').textContent()).toBe(`Playing as ${emojiName(32)}`);
    expect(errors).toEqual([]);
    await page.context().close();
  });

  it('"You are ..." in the lobby shows the name the server stored, and follows a rename in another tab', async () => {
    const { page, errors } = await lobby();
    const input = page.getByRole('textbox', { name: 'Your name' });

    // The name as the server stores it (NFKC: the ligature "ﬁ" is "fi").
    const mine = `\uFB01sh ${Date.now() % 100000}`;
    await input.fill(mine);
    await page.getByRole('button', { name: 'Change name' }).click();
    await expect.poll(() => page.locator('p.note').textContent()).toBe(`You are ${mine.normalize('NFKC')}`);
    // A rename in another tab of the same player: this lobby follows it.
    const other = await page.context().newPage();
    await other.goto(`${env.server.url}/`);
    await other.waitForSelector('#server-status.ok');
    const next = `Renamed ${Date.now() % 100000}`;
    await other.getByRole('textbox', { name: 'Your name' }).fill(next);
    await other.getByRole('button', { name: 'Change name' }).click();
    await expect.poll(() => other.locator('p.note').textContent()).toBe(`You are ${next}`);
    await expect.poll(() => page.locator('p.note').textContent()).toBe(`You are ${next}`);
    expect(errors).toEqual([]);
    await page.context().close();
  });
});
