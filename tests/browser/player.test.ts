// A player's page in Chromium, on a database filled with a few hundred matches: the ten newest,
// then "More matches" a page at a time until the list holds every match the API has.
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { fill } from '../../bench/store-fill.ts';
import { openDatabase } from '../../server/database.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';
import { ROOT } from '../support/server-process.ts';

interface Page<T> { readonly matches: T[] }

describe.skipIf(!chromiumAvailable())('a player\'s page in Chromium', () => {
  const env = serverAndChromium((dbPath) => {
    const { db } = openDatabase(dbPath, join(ROOT, 'migrations'));
    fill(db, { players: 12, matches: 300, seed: 11 });
    db.close();
  });

  const get = async <T>(path: string): Promise<T> => (await fetch(`${env.server.url}${path}`)).json() as Promise<T>;

  it('lists the ten newest matches, then every other one a page at a time', async () => {
    // The busiest player on the nine-ball leaderboard, and all of their matches from the API.
    const board = await get<{ entries: { player: { id: string }; games: number }[] }>('/api/leaderboard?kind=nineball&limit=100');
    const busiest = [...board.entries].sort((a, b) => b.games - a.games)[0]!.player.id;
    const ids: number[] = [];
    for (let offset = 0; ; offset += 100) {
      const page = await get<Page<{ id: number }>>(`/api/matches?player=${busiest}&limit=100&offset=${offset}`);
      ids.push(...page.matches.map((m) => m.id));
      if (page.matches.length < 100) break;
    }
    expect(ids.length).toBeGreaterThan(30);

    const page = await env.browser.newPage();
    const errors: string[] = [];
    page.on('pageerror', (err) => errors.push(err.message));
    await page.goto(`${env.server.url}/player/${busiest}`);
    const list = page.getByRole('list', { name: 'Recent matches' });
    await expect.poll(() => list.getByRole('listitem').count()).toBe(10);
    const more = page.getByRole('button', { name: 'More matches' });
    let shown = 10;
    while (await more.isVisible()) {
      await more.click();
      const expected = Math.min(ids.length, shown + 20);
      await expect.poll(() => list.getByRole('listitem').count()).toBe(expected);
      shown = expected;
    }
    // Every match once, newest first, each a link to its replay.
    const hrefs = await list.getByRole('link').evaluateAll((links) => links.map((a) => a.getAttribute('href')));
    expect(hrefs).toEqual(ids.map((id) => `/match/${id}`));
    expect(errors).toEqual([]);
    await page.close();
  }, 60_000);
});
