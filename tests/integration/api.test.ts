// The HTTP API against a real server and SQLite file: ratings from matches played over the
// protocol, records only from verified play, practice runs the server replays itself from seeds it
// issued, and a 400 naming the parameter for every bad request, which stores nothing.
// (tests/integration/practice.test.ts: the seeds, the standing records and the rate limits.)
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { chooseShot } from '../../bots/strategy.ts';
import { simulate } from '../../shared/physics/index.ts';
import { openDatabase } from '../../server/database.ts';
import { Store } from '../../server/store/index.ts';
import { hashToken } from '../../server/tokens.ts';
import { newGame, playShot, practiceRun, practiceStart, PRACTICE_OPPONENT, type Game, type PracticeKind, type PracticeShot } from '../../shared/rules/index.ts';
import { ask, connect, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { ROOT, startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

let server: ServerProcess;
let url: string;
const seats: Seat[] = [];
/** Tokens of two players whose eight-ball ratings are established before the server starts. */
const SEEDED = { 'Rated-A': 'seeded-token-a', 'Rated-B': 'seeded-token-b' };

beforeAll(async () => {
  const path = join(tempDir(), 'baize.db');
  // Two players with established eight-ball ratings (1500, RD 80 after 20 games), as if they had
  // played their way onto the board: a board of real games takes far more than a test plays.
  const { db } = openDatabase(path, join(ROOT, 'migrations'));
  const store = new Store(db);
  for (const [name, token] of Object.entries(SEEDED)) {
    const p = store.createPlayer(name, hashToken(token));
    db.prepare("INSERT INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES ('eightball', ?, 1500, 80, 0.06, 20, 10, 0)").run(p.id);
  }
  db.close();
  // No minimum time of play: these matches take milliseconds (the rule's own test moves a clock).
  // Practice limits these tests never meet either (practice.test.ts tests them).
  server = await startServerProcess({ BAIZE_DB: path, BAIZE_RATED_MIN_PLAY_S: '0', BAIZE_PRACTICE_PER_MINUTE: '100000', BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE: '100000' });
  url = wsUrl(server.url);
});
afterAll(async () => {
  await Promise.all(seats.map((s) => s.client.close(200)));
  await server.stop('SIGKILL');
});

async function get(path: string): Promise<{ status: number; body: any }> {
  const res = await fetch(`${server.url}${path}`);
  return { status: res.status, body: await res.json() };
}

async function post(path: string, body: unknown): Promise<{ status: number; body: any }> {
  const res = await fetch(`${server.url}${path}`, { method: 'POST', headers: { 'content-type': 'application/json' }, body: typeof body === 'string' ? body : JSON.stringify(body) });
  return { status: res.status, body: await res.json() };
}

/** A seed the server issues to the player for a run of `kind`. */
async function issued(p: Seat, kind: PracticeKind): Promise<number> {
  const r = await post('/api/practice/start', { token: p.token, kind });
  expect(r.status, JSON.stringify(r.body)).toBe(200);
  return r.body.seed as number;
}

async function player(name: string): Promise<Seat> {
  const s = await connect(url, name in SEEDED ? { token: SEEDED[name as keyof typeof SEEDED] } : { name });
  seats.push(s);
  return s;
}

/**
 * A match between a and b. With `fouls`, an eight-ball match where each player in turn strokes the
 * cue ball a few centimetres into nothing (a foul: the turn passes; in nine-ball the third in a
 * row would lose the rack) until each has played that many, then `loser` concedes; without, a
 * nine-ball match the sound bots play to its end.
 */
async function match(a: Seat, b: Seat, loser: Seat, fouls?: number): Promise<number> {
  const created = await ask(a, { type: 'create', kind: fouls === undefined ? 'nineball' : 'eightball' });
  if (created.type !== 'room') throw new Error(JSON.stringify(created));
  const room = created.room.id;
  await ask(b, { type: 'join', room });
  await until(a, room, (r) => r.status === 'playing');
  for (let i = 0; a.rooms.get(room)!.status === 'playing' && (fouls === undefined || i < 2 * fouls); i++) {
    const r = a.rooms.get(room)!;
    const seat = r.game!.turn === a.player.id ? a : b;
    await until(seat, room, (x) => x.stateId === r.stateId);
    if (fouls === undefined) await playTurn(seat, room);
    else await ask(seat, { type: 'shot', room, stateId: r.stateId, shot: { ball: 'cue', heading: Math.PI, speed: 0.05, side: 0, top: 0 } });
    // A shot that wins the game comes as two messages: the shot (its game won, the status still
    // `playing` in a's view) and then the room's new state. Wait for both, or the loop reads
    // `playing` between them and plays on in a finished game.
    await until(a, room, (x) => x.stateId > r.stateId && (x.status !== 'playing' || x.game?.winner === null));
  }
  if (a.rooms.get(room)!.status === 'playing') await ask(loser, { type: 'concede', room });
  await until(a, room, (r) => r.status === 'over');
  return a.rooms.get(room)!.view!.match!;
}

/** Whether a shot keeps the player at the table having scored (a pot, a point). */
function scores(game: Game, shot: PracticeShot, playerId: string): Game | null {
  try {
    const next = playShot(game, { ...shot.shot, player: playerId }, shot.cueBall).game;
    const v = next.verdict!;
    return !v.foul && (v.potted.length > 0 || (v.points[playerId] ?? 0) > 0) ? next : null;
  } catch {
    return null;
  }
}

/**
 * A practice run that scores: a first shot found by a fan of headings and speeds (from a few
 * places in hand), then the sound bot while it keeps the table (at most `max` shots).
 */
function scoringRun(kind: PracticeKind, playerId: string, seed: number, max = 8): PracticeShot[] {
  let game: Game = practiceStart(kind, playerId, seed);
  const cue = game.balls.find((b) => b.id === (kind === 'threecushion' ? 'white' : 'cue'))!;
  const places = game.ballInHand === false ? [undefined] : [undefined, { x: cue.x, y: cue.y + 0.1 }, { x: cue.x, y: cue.y - 0.1 }];
  const shots: PracticeShot[] = [];
  search: for (const cueBall of places) {
    for (const speed of [3, 5, 7]) {
      for (let i = 0; i < 360; i++) {
        const shot: PracticeShot = { shot: { ball: cue.id, heading: (i * Math.PI) / 180, speed, side: kind === 'threecushion' ? 0.3 : 0, top: 0 }, ...(cueBall ? { cueBall } : {}) };
        const next = scores(game, shot, playerId);
        if (next) {
          shots.push(shot);
          game = next;
          break search;
        }
      }
    }
  }
  while (shots.length > 0 && shots.length < max && game.winner === null && game.turn === playerId) {
    const { player: _p, ...shot } = chooseShot(game, 'sound', (scene, s) => simulate(scene, s));
    shots.push({ shot });
    game = playShot(game, { ...shot, player: playerId }).game;
  }
  return shots;
}

describe('the HTTP API', () => {
  it('rates real games once, ranks established players only, and limits the rated games of a pair a day', async () => {
    const a = await player('Rated-A');
    const b = await player('Rated-B');
    const ids: number[] = [];
    for (let i = 0; i < 3; i++) ids.push(await match(a, b, b, 3));
    const board = await get('/api/leaderboard?kind=eightball');
    expect(board.status).toBe(200);
    expect(board.body.total).toBe(2);
    const [entryA, entryB] = board.body.entries;
    expect(entryA).toMatchObject({ rank: 1, player: a.player, games: 23, wins: 13, provisional: false });
    expect(entryB).toMatchObject({ rank: 2, player: b.player, games: 23, wins: 10, provisional: false });
    expect(entryA.rating).toBeGreaterThan(1500);
    expect(entryB.rating).toBeLessThan(1500);
    // Each result moved the ratings: three matches, all rated, newest first.
    const list = await get(`/api/matches?player=${a.player.id}&kind=eightball`);
    expect(list.body.matches.map((m: any) => m.id)).toEqual([...ids].reverse());
    for (const m of list.body.matches) expect(m.result).toEqual({ winner: a.player.id, reason: 'concession', rated: true });
    const page = await get(`/api/players/${a.player.id}`);
    expect(page.body).toMatchObject({ id: a.player.id, name: 'Rated-A', games: 23, wins: 13, ratings: { eightball: { games: 23, wins: 13, provisional: false } } });
    expect(page.body.recent).toHaveLength(3);
    // A fourth real game of the pair within 24 hours is played and kept, but not rated.
    const fourth = await match(a, b, b, 3);
    expect((await get(`/api/matches/${fourth}`)).body.result).toEqual({ winner: a.player.id, reason: 'concession', rated: false, unrated: 'pair-limit' });
    expect([...a.rooms.values()].at(-1)!.view).toMatchObject({ rated: false, unrated: 'at most 3 rated matches of a kind between the same two players in 24 hours' });
    // A newcomer's real win is rated: their own page shows the rating, marked provisional; the
    // board does not list it.
    const c = await player('Rated-C');
    await match(c, b, b, 3);
    const newcomer = await get(`/api/players/${c.player.id}`);
    expect(newcomer.body.ratings.eightball).toMatchObject({ games: 1, wins: 1, provisional: true });
    expect(newcomer.body.ratings.eightball.rating).toBeGreaterThan(1500);
    const after = await get('/api/leaderboard?kind=eightball');
    expect(after.body.total).toBe(2);
    expect(after.body.entries.map((e: any) => e.player.id)).toEqual([a.player.id, b.player.id]);
    // A match conceded after one shot each is not rated.
    const quick = await match(c, b, c, 1);
    expect((await get(`/api/matches/${quick}`)).body.result).toMatchObject({ rated: false, unrated: 'few-shots' });
    expect((await get(`/api/players/${c.player.id}`)).body.ratings.eightball.games).toBe(1);
  }, 120_000);

  it('serves each match as a record that replays to what the server broadcast', async () => {
    const a = await player('Replay-A');
    const b = await player('Replay-B');
    const id = await match(a, b, a);
    const rec = await get(`/api/matches/${id}`);
    expect(rec.status).toBe(200);
    const final = a.rooms.get([...a.rooms.keys()].at(-1)!)!;
    expect(rec.body).toMatchObject({ id, kind: 'nineball', raceTo: 1, status: 'over', result: { winner: final.view!.winner } });
    const { replayMatch } = await import('../../shared/rules/index.ts');
    const replayed = replayMatch(rec.body);
    const broadcast = a.log.filter((m) => m.type === 'shot' && m.match === id).map((m) => (m as any).outcome.hash);
    expect(replayed.shots.map((s) => s.hash)).toEqual(broadcast);
    expect(replayed.shots.every((s) => s.recorded === s.hash)).toBe(true);
    expect(replayed.shots.length).toBeGreaterThan(2);
    expect(replayed.game).toEqual(final.game);
  }, 60_000);

  it('plays practice runs itself and keeps their records; the client sends shots, never a score', async () => {
    const p = await player('Practiser');
    for (const kind of ['snooker', 'nineball', 'threecushion'] as const) {
      // A run that scores, found by playing it locally the way the server will.
      const seed = await issued(p, kind);
      const shots = scoringRun(kind, p.player.id, seed);
      const local = practiceRun(kind, p.player.id, seed, shots);
      expect(local.score, kind).toBeGreaterThan(0);
      const res = await post('/api/practice', { token: p.token, kind, seed, shots, score: 1_000_000 });
      expect(res.status, JSON.stringify(res.body)).toBe(200);
      expect(res.body).toMatchObject({ kind, seed, score: local.score });
      if (kind !== 'nineball') {
        const records = await get(`/api/records?kind=${kind}&source=practice`);
        expect(records.body.entries.some((e: any) => e.practice === res.body.id && e.player.id === p.player.id)).toBe(true);
      }
    }
    // The player's page shows their best record of each kind.
    const page = await get(`/api/players/${p.player.id}`);
    for (const kind of ['snooker', 'threecushion']) {
      const all = (await get(`/api/records?kind=${kind}&source=practice&limit=100`)).body.entries.filter((e: any) => e.player.id === p.player.id);
      expect(page.body.records.find((r: any) => r.kind === kind)?.value).toBe(Math.max(...all.map((e: any) => e.value)));
    }
  }, 120_000);

  it('answers every bad parameter with a 400 naming it, unknown ids with a 404, and stores nothing', async () => {
    const p = await player('Careless');
    const before = await get('/api/records?kind=snooker&source=practice&limit=100');
    const bad: [string, RegExp][] = [
      ['/api/leaderboard', /kind/],
      ['/api/leaderboard?kind=pool', /kind/],
      ['/api/leaderboard?kind=nineball&limit=0', /limit/],
      ['/api/leaderboard?kind=nineball&limit=101', /limit/],
      ['/api/leaderboard?kind=nineball&limit=ten', /limit/],
      ['/api/leaderboard?kind=nineball&offset=-1', /offset/],
      ['/api/records?kind=eightball', /kind/],
      ['/api/records?kind=snooker&source=both', /source/],
      ['/api/matches?player=abc', /player/],
      ['/api/matches?kind=chess', /kind/],
      ['/api/matches/abc', /id/],
      ['/api/players/-4', /id/],
    ];
    for (const [path, names] of bad) {
      const r = await get(path);
      expect(r.status, path).toBe(400);
      expect(r.body.message, path).toMatch(names);
    }
    expect((await get('/api/matches/999999')).status).toBe(404);
    expect((await get('/api/players/999999')).status).toBe(404);
    expect((await get('/api/nothing')).status).toBe(404);
    const shot = { ball: 'cue', heading: 0, speed: 3, side: 0, top: 0 };
    // Refused runs do not use up their seeds.
    const seed = await issued(p, 'snooker');
    const nineball = await issued(p, 'nineball');
    const posts: [unknown, number, RegExp][] = [
      ['{"token":', 400, /JSON/],
      [{ token: p.token, kind: 'snooker', seed }, 400, /shots/],
      [{ token: p.token, kind: 'snooker', shots: [{ shot }] }, 400, /seed/],
      [{ token: p.token, kind: 'snooker', seed: -1, shots: [{ shot }] }, 400, /seed/],
      [{ token: p.token, kind: 'eightball', seed, shots: [{ shot }] }, 400, /kind/],
      [{ token: 'forged', kind: 'snooker', seed, shots: [{ shot }] }, 400, /token/],
      [{ token: p.token, kind: 'snooker', seed, shots: [{ shot: { ...shot, speed: 'NaN' } }] }, 400, /speed/],
      [{ token: p.token, kind: 'snooker', seed, shots: [{ shot: { ...shot, side: 0.45, top: 0.45 } }] }, 400, /shots\[0\].*miscue/],
      [{ token: p.token, kind: 'snooker', seed, shots: [{ shot: { ...shot, ball: 'red1' } }] }, 400, /shots\[0\]/],
      [{ token: p.token, kind: 'nineball', seed: nineball, shots: [{ shot: { ...shot, speed: 0.3 } }, { shot }] }, 400, /shots\[1\]: the run ended/],
    ];
    for (const [body, status, message] of posts) {
      const r = await post('/api/practice', body);
      expect(r.status, JSON.stringify(body)).toBe(status);
      expect(r.body.message, JSON.stringify(body)).toMatch(message);
    }
    expect((await get('/api/records?kind=snooker&source=practice&limit=100')).body).toEqual(before.body);
    expect((await get(`/api/players/${p.player.id}`)).body).toMatchObject({ games: 0, records: [] });
    // Both seeds are still good for a run.
    expect((await post('/api/practice', { token: p.token, kind: 'snooker', seed, shots: [{ shot }] })).status).toBe(200);
    expect((await post('/api/practice', { token: p.token, kind: 'nineball', seed: nineball, shots: [{ shot: { ...shot, speed: 0.3 } }] })).status).toBe(200);
  }, 60_000);
});
