// Practice runs against a real server and SQLite file (issue 36): only from seeds the server
// issued, each once; one standing practice record per player, listed apart from match records;
// requests limited per player and per address; three-cushion runs that last past the first point.
import fc from 'fast-check';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { playShot, practiceRun, practiceStart, type PracticeKind, type PracticeShot } from '../../shared/rules/index.ts';
import { connect, wsUrl, type Seat } from '../support/game-clients.ts';
import { snookerBreak } from '../support/snooker-break.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

let server: ServerProcess;
const seats: Seat[] = [];

beforeAll(async () => {
  // Limits no test here meets, but the one that sets its own.
  server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db'), BAIZE_PRACTICE_PER_MINUTE: '100000', BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE: '100000' });
});
afterAll(async () => {
  await Promise.all(seats.map((s) => s.client.close(200)));
  await server.stop('SIGKILL');
});

interface Answer {
  status: number;
  body: any;
  retryAfter: string | null;
}

async function request(base: string, path: string, body?: unknown): Promise<Answer> {
  const init = body === undefined ? {} : { method: 'POST', headers: { 'content-type': 'application/json' }, body: typeof body === 'string' ? body : JSON.stringify(body) };
  const res = await fetch(`${base}${path}`, init);
  return { status: res.status, body: await res.json(), retryAfter: res.headers.get('retry-after') };
}

const get = (path: string) => request(server.url, path);
const post = (path: string, body: unknown) => request(server.url, path, body);

async function player(name: string, on = server): Promise<Seat> {
  const s = await connect(wsUrl(on.url), { name });
  seats.push(s);
  return s;
}

async function issued(p: Seat, kind: PracticeKind): Promise<number> {
  const r = await post('/api/practice/start', { token: p.token, kind });
  expect(r.status, JSON.stringify(r.body)).toBe(200);
  return r.body.seed as number;
}


/** Each player's practice records of a kind on the practice board. */
async function practiceBoard(kind: PracticeKind): Promise<any[]> {
  const r = await get(`/api/records?kind=${kind}&source=practice&limit=100`);
  expect(r.status).toBe(200);
  return r.body.entries;
}

const FOUL = { ball: 'cue', heading: 0, speed: 3, side: 0, top: 0 };

describe('practice seeds', () => {
  it('are issued by the server: a 32-bit number, new for each run, to a known player for a practice kind', async () => {
    const p = await player('Seeded');
    const a = await post('/api/practice/start', { token: p.token, kind: 'snooker' });
    const b = await post('/api/practice/start', { token: p.token, kind: 'snooker' });
    for (const r of [a, b]) {
      expect(r.status).toBe(200);
      expect(r.body).toMatchObject({ kind: 'snooker' });
      expect(Number.isInteger(r.body.seed) && r.body.seed >= 0 && r.body.seed < 2 ** 32).toBe(true);
      expect(r.body.expiresAt).toBeGreaterThan(Date.now() + 3600_000);
    }
    expect(a.body.seed).not.toBe(b.body.seed);
    expect(await post('/api/practice/start', { token: 'forged', kind: 'snooker' })).toMatchObject({ status: 400, body: { error: 'bad-token' } });
    expect(await post('/api/practice/start', { token: p.token, kind: 'eightball' })).toMatchObject({ status: 400, body: { error: 'bad-body' } });
    expect((await get('/api/practice/start')).status).toBe(405);
  });

  it('refuse with a 409 a made-up seed, another player\'s, another kind\'s, and one used already; nothing is stored', async () => {
    const a = await player('Honest-A');
    const b = await player('Honest-B');
    const run = [{ shot: FOUL }];
    const mine = await issued(a, 'snooker');
    const theirs = await issued(b, 'snooker');
    const before = await practiceBoard('snooker');
    const refusals: [unknown, string][] = [
      [{ token: a.token, kind: 'snooker', seed: (mine + 1) % 2 ** 32, shots: run }, 'seed-not-issued'],
      [{ token: a.token, kind: 'snooker', seed: theirs, shots: run }, 'seed-not-issued'],
      [{ token: a.token, kind: 'threecushion', seed: mine, shots: [{ shot: { ...FOUL, ball: 'white' } }] }, 'seed-not-issued'],
    ];
    for (const [body, error] of refusals) {
      const r = await post('/api/practice', body);
      expect(r.status, JSON.stringify(body)).toBe(409);
      expect(r.body.error).toBe(error);
      expect(r.body.message).toMatch(/^seed: .*\/api\/practice\/start/);
    }
    // Made-up seeds of any value (property): all refused.
    await fc.assert(
      fc.asyncProperty(fc.integer({ min: 0, max: 2 ** 32 - 1 }), async (seed) => {
        fc.pre(seed !== mine);
        const r = await post('/api/practice', { token: a.token, kind: 'snooker', seed, shots: run });
        expect(r.status).toBe(409);
      }),
      { numRuns: 25 },
    );
    expect(await practiceBoard('snooker')).toEqual(before);
    // The seeds stay good for their own players, once.
    expect((await post('/api/practice', { token: b.token, kind: 'snooker', seed: theirs, shots: run })).status).toBe(200);
    expect((await post('/api/practice', { token: a.token, kind: 'snooker', seed: mine, shots: run })).status).toBe(200);
    const again = await post('/api/practice', { token: a.token, kind: 'snooker', seed: mine, shots: run });
    expect(again).toMatchObject({ status: 409, body: { error: 'seed-used' } });
    expect(again.body.message).toMatch(/already used/);
  });

  it('decide the rack: a nine-ball run plays from the rack of its issued seed', async () => {
    const p = await player('Racked');
    const seed = await issued(p, 'nineball');
    const shots = [{ shot: { ...FOUL, speed: 8 } }];
    const r = await post('/api/practice', { token: p.token, kind: 'nineball', seed, shots });
    expect(r.status).toBe(200);
    expect(r.body).toMatchObject({ seed, score: practiceRun('nineball', p.player.id, seed, shots).score });
  });
});

describe('practice records', () => {
  it('stand one per player and kind: the same run posted again and again is listed once; only a better one replaces it', async () => {
    const p = await player('Flooder');
    const other = await player('Bystander');
    const full = snookerBreak(p.player.id, 4);
    const breakOf = (shots: PracticeShot[]) => practiceRun('snooker', p.player.id, 0, shots).achievements[0]!.value;
    const short = full.slice(0, 2);
    expect(breakOf(full)).toBeGreaterThan(breakOf(short));
    const submit = async (who: Seat, shots: PracticeShot[]) => {
      const r = await post('/api/practice', { token: who.token, kind: 'snooker', seed: await issued(who, 'snooker'), shots });
      expect(r.status, JSON.stringify(r.body)).toBe(200);
      return r.body;
    };
    const mineOn = async () => (await practiceBoard('snooker')).filter((e) => e.player.id === p.player.id);
    // The shorter break, posted 20 times: one entry, the first run's.
    const first = await submit(p, short);
    expect(first.records).toEqual([{ what: 'break', value: breakOf(short), standing: true }]);
    for (let i = 0; i < 19; i++) expect((await submit(p, short)).records[0].standing).toBe(false);
    expect(await mineOn()).toMatchObject([{ value: breakOf(short), practice: first.id, source: 'practice' }]);
    // Someone else's run does not touch it.
    await submit(other, short);
    expect(await mineOn()).toMatchObject([{ practice: first.id }]);
    // A better run replaces it; a worse one after it does not.
    const better = await submit(p, full);
    expect(better.records[0].standing).toBe(true);
    expect((await submit(p, short)).records[0].standing).toBe(false);
    expect(await mineOn()).toMatchObject([{ value: breakOf(full), practice: better.id }]);
    // The player's page shows that best.
    const page = await get(`/api/players/${p.player.id}`);
    expect(page.body.records).toMatchObject([{ kind: 'snooker', value: breakOf(full), practice: better.id, source: 'practice' }]);
    // No player twice on the board.
    const ids = (await practiceBoard('snooker')).map((e) => e.player.id);
    expect(new Set(ids).size).toBe(ids.length);
  }, 60_000);

  it('are listed apart from match records: the default list is of matches', async () => {
    const p = await player('Apart');
    const seed = await issued(p, 'snooker');
    const shots = snookerBreak(p.player.id, 2);
    const run = await post('/api/practice', { token: p.token, kind: 'snooker', seed, shots });
    expect(run.status).toBe(200);
    for (const path of ['/api/records?kind=snooker', '/api/records?kind=snooker&source=match']) {
      const list = await get(`${path}&limit=100`);
      expect(list.status).toBe(200);
      expect(list.body.source).toBe('match');
      expect(list.body.entries.filter((e: any) => e.practice !== undefined || e.source !== 'match')).toEqual([]);
    }
    const practice = await get('/api/records?kind=snooker&source=practice&limit=100');
    expect(practice.body.source).toBe('practice');
    expect(practice.body.entries.some((e: any) => e.practice === run.body.id && e.source === 'practice' && e.match === undefined)).toBe(true);
    expect(practice.body.entries.map((e: any) => e.rank)).toEqual(practice.body.entries.map((_: unknown, i: number) => i + 1));
  }, 60_000);
});

describe('a three-cushion practice run', () => {
  it('goes on past the first point', async () => {
    const p = await player('Carom');
    // An opening point (three-cushion's layout does not depend on the seed), then a miss.
    const start = practiceStart('threecushion', p.player.id, 0);
    let point: PracticeShot | undefined;
    for (let i = 0; i < 360 && !point; i++) {
      const shot = { ball: 'white', heading: (i * Math.PI) / 180, speed: 3, side: 0.3, top: 0 };
      const v = playShot(start, { ...shot, player: p.player.id }).game.verdict!;
      if (!v.foul && v.points[p.player.id] === 1) point = { shot };
    }
    expect(point).toBeDefined();
    const shots = [point!, { shot: { ball: 'white', heading: 0, speed: 0.2, side: 0, top: 0 } }];
    const r = await post('/api/practice', { token: p.token, kind: 'threecushion', seed: await issued(p, 'threecushion'), shots });
    expect(r.status, JSON.stringify(r.body)).toBe(200);
    expect(r.body).toMatchObject({ shots: 2, score: 1, records: [{ what: 'run', value: 1 }] });
  });
});

describe('practice requests', () => {
  it('are limited per player and per address: a 429 with Retry-After, and nothing stored', async () => {
    // A player: 5 at once, then one every 10 s; the address: 10 at once.
    const limited = await startServerProcess({ BAIZE_DB: join(tempDir(), 'limited.db'), BAIZE_PRACTICE_PER_MINUTE: '6', BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE: '60' });
    try {
      const [a, b, c] = [await player('Busy-A', limited), await player('Busy-B', limited), await player('Busy-C', limited)];
      const start = (who: Seat) => request(limited.url, '/api/practice/start', { token: who.token, kind: 'snooker' });
      // A player: five requests, then refused (the address has taken 6 of its 10).
      const seeds: number[] = [];
      for (let i = 0; i < 5; i++) {
        const r = await start(a);
        expect(r.status).toBe(200);
        seeds.push(r.body.seed);
      }
      const over = await request(limited.url, '/api/practice', { token: a.token, kind: 'snooker', seed: seeds[0], shots: [{ shot: FOUL }] });
      expect(over).toMatchObject({ status: 429, body: { error: 'rate-limited' } });
      expect(over.body.message).toMatch(/too many practice requests from you: try again in \d+ s/);
      expect(Number(over.retryAfter)).toBeGreaterThanOrEqual(1);
      expect(Number(over.retryAfter)).toBeLessThanOrEqual(10); // a token every 10 s
      // Another player from the same address has their own, until the address's 10 are gone.
      for (let i = 0; i < 4; i++) expect((await start(b)).status).toBe(200);
      const address = await start(c);
      expect(address).toMatchObject({ status: 429, body: { error: 'rate-limited' } });
      expect(address.body.message).toMatch(/from this address/);
      expect(Number(address.retryAfter)).toBeGreaterThanOrEqual(1);
      // Refused before its body is read: even a body that is not JSON.
      expect((await request(limited.url, '/api/practice', '{"token":')).status).toBe(429);
      // The refused run was not stored; reads are not limited.
      const board = await request(limited.url, '/api/records?kind=snooker&source=practice');
      expect(board).toMatchObject({ status: 200, body: { entries: [] } });
    } finally {
      await limited.stop('SIGKILL');
    }
  }, 60_000);
});
