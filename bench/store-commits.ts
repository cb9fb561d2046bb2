// npm run bench:store-commits [-- --seconds 5 --rooms 1,8,32 --finishes 200]
// What the store's writes cost: a move (a room's new state with its action: saveChanges, guarded by
// the room's stateId, the one transaction of every shot) with 1, 8 and 32 rooms writing at once,
// then finished matches (result, both ratings, a record), through the AsyncStore on a SQLite file
// and on a PostgreSQL started here on 127.0.0.1 with fsync on, as a production server runs. For
// PostgreSQL also its committed transactions per move, read from pg_stat_database. The room state
// is a real snooker game's JSON. Prints markdown; asserts nothing.
import { rmSync } from 'node:fs';
import { cpus } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import pg from 'pg';
import { newGame } from '../shared/rules/index.ts';
import { openStore, type AsyncStore } from '../server/store/index.ts';
import { postgresAvailable, startPostgres } from '../tests/support/postgres.ts';
import { ROOT, tempDir } from '../tests/support/server-process.ts';

const { values } = parseArgs({
  options: {
    seconds: { type: 'string', default: '5' },
    rooms: { type: 'string', default: '1,8,32' },
    finishes: { type: 'string', default: '200' },
  },
});
const seconds = Number(values.seconds);
const roomCounts = values.rooms.split(',').map(Number);
const finishes = Number(values.finishes);
if (!(seconds > 0 && seconds <= 600) || !roomCounts.every((n) => Number.isInteger(n) && n >= 1 && n <= 1000) || !Number.isInteger(finishes) || finishes < 1 || finishes > 10_000) {
  console.error('usage: npm run bench:store-commits -- [--seconds 5 (up to 600)] [--rooms 1,8,32 (each 1-1000)] [--finishes 200 (1-10000)]');
  process.exit(2);
}
const MIGRATIONS = join(ROOT, 'migrations');
const GAME = newGame('snooker', ['1', '2'], { seed: 5 });
const stateJson = (stateId: number) => JSON.stringify({ id: 'room', kind: 'snooker', stateId, status: 'playing', seats: ['1', '2'], game: GAME, deadline: null });
const ACTION = JSON.stringify({ type: 'shot', player: '1', shot: { angle: 1.2345, power: 0.75, spin: { x: 0.1, y: -0.2 }, elevation: 0 }, hash: 'f'.repeat(16) });

interface Room {
  readonly id: string;
  readonly matchId: number;
  stateId: number;
}

interface Cell {
  readonly store: string;
  readonly what: string;
  readonly n: number;
  readonly perSecond: number;
  readonly p50: number;
  readonly p99: number;
  /** PostgreSQL's committed transactions per write, when measured. */
  readonly xacts?: number;
}

const quantile = (sorted: readonly number[], q: number): number => sorted[Math.max(0, Math.ceil(q * sorted.length) - 1)]!;

function cell(store: string, what: string, ms: number[], elapsedMs: number, xacts?: number): Cell {
  ms.sort((a, b) => a - b);
  return { store, what, n: ms.length, perSecond: (ms.length * 1000) / elapsedMs, p50: quantile(ms, 0.5), p99: quantile(ms, 0.99), ...(xacts === undefined ? {} : { xacts }) };
}

/** Rooms, each with two players and a match in play. */
async function setUp(store: AsyncStore, n: number): Promise<{ rooms: Room[]; players: number[] }> {
  const players: number[] = [];
  for (let i = 0; i < Math.max(2 * n, 2 * finishes); i++) players.push((await store.createPlayer(`P${i}`, Buffer.alloc(32, 0).fill(i % 256, 0, 1).fill(Math.floor(i / 256), 1, 2).fill(7, 2, 3))).id);
  const rooms: Room[] = [];
  for (let i = 0; i < n; i++) {
    const id = `room${i}`;
    await store.createRoom({ id, kind: 'snooker', raceTo: 1, private: false, shotClock: 0, createdBy: players[2 * i]!, status: 'playing', state: stateJson(0) });
    const matchId = await store.createMatch({ roomId: id, kind: 'snooker', raceTo: 1, player1: players[2 * i]!, player2: players[2 * i + 1]!, seed: 1, start: JSON.stringify(GAME) });
    rooms.push({ id, matchId, stateId: 0 });
  }
  return { rooms, players };
}

/** Each room plays moves one after another for `seconds`, all rooms at once. */
async function moves(store: AsyncStore, rooms: readonly Room[]): Promise<{ ms: number[]; elapsed: number }> {
  const ms: number[] = [];
  const t0 = performance.now();
  const end = t0 + seconds * 1000;
  await Promise.all(
    rooms.map(async (r) => {
      while (performance.now() < end) {
        const next = r.stateId + 1;
        const t = performance.now();
        await store.saveChanges({ roomId: r.id, status: 'playing', state: stateJson(next), expectStateId: r.stateId, action: { matchId: r.matchId, seq: next, json: ACTION } });
        ms.push(performance.now() - t);
        r.stateId = next;
      }
    }),
  );
  return { ms, elapsed: performance.now() - t0 };
}

/** Matches finished one after another, each between its own pair (no pair limit). */
async function finished(store: AsyncStore, players: readonly number[], room: Room): Promise<{ ms: number[]; elapsed: number }> {
  const ms: number[] = [];
  const t0 = performance.now();
  for (let i = 0; i < finishes; i++) {
    const [winner, loser] = [players[i]!, players[finishes + i]!];
    const matchId = await store.createMatch({ roomId: room.id, kind: 'snooker', raceTo: 1, player1: winner, player2: loser, seed: i, start: '{}' });
    const t = performance.now();
    await store.saveChanges({
      roomId: room.id,
      status: 'over',
      state: stateJson(0),
      result: { matchId, kind: 'snooker', winner, loser, how: 'played', scores: '[1,0]', rated: true, records: [{ what: 'break', player: winner, value: 40, better: 40 }] },
    });
    ms.push(performance.now() - t);
  }
  return { ms, elapsed: performance.now() - t0 };
}

async function run(label: string, open: () => Promise<AsyncStore>, xactCount?: () => Promise<number>): Promise<Cell[]> {
  const cells: Cell[] = [];
  const setup = await open();
  const { rooms, players } = await setUp(setup, Math.max(...roomCounts));
  await setup.close();
  for (const n of roomCounts) {
    // A store of its own for each cell, closed before counting: its connections' statistics are
    // flushed as they end.
    const before = await xactCount?.();
    const store = await open();
    const { ms, elapsed } = await moves(store, rooms.slice(0, n));
    await store.close();
    const after = await xactCount?.();
    cells.push(cell(label, `move (state + action), ${n} room${n === 1 ? '' : 's'} at once`, ms, elapsed, before === undefined ? undefined : (after! - before) / ms.length));
  }
  const before = await xactCount?.();
  const store = await open();
  const { ms, elapsed } = await finished(store, players, rooms[0]!);
  await store.close();
  const after = await xactCount?.();
  // Each finish also opened its match (one more transaction), counted here and taken off.
  cells.push(cell(label, 'finish (result, 2 ratings, a record), one at a time', ms, elapsed, before === undefined ? undefined : (after! - before) / ms.length - 1));
  return cells;
}

const cells: Cell[] = [];
const dir = tempDir('baize-bench-commits-');
try {
  const path = join(dir, 'baize.db');
  cells.push(...(await run('SQLite (WAL, synchronous=FULL)', async () => (await openStore({ dbPath: path, migrationsDir: MIGRATIONS })).store)));
} finally {
  rmSync(dir, { recursive: true, force: true });
}
if (postgresAvailable()) {
  const server = await startPostgres({ durable: true });
  try {
    const url = server.url;
    const name = url.slice(url.lastIndexOf('/') + 1);
    const admin = new pg.Client({ connectionString: `${url.slice(0, url.lastIndexOf('/'))}/postgres` });
    await admin.connect();
    const xactCount = async () => {
      // A closed connection's statistics reach the shared counters as its backend exits.
      await new Promise((r) => setTimeout(r, 300));
      return Number((await admin.query<{ n: string }>('SELECT xact_commit AS n FROM pg_stat_database WHERE datname = $1', [name])).rows[0]!.n);
    };
    cells.push(...(await run('PostgreSQL (pg pool, fsync on)', async () => (await openStore({ dbPath: 'unused', migrationsDir: MIGRATIONS, databaseUrl: url })).store, xactCount)));
    await admin.end();
  } finally {
    await server.stop();
  }
}

const fmt = (x: number, digits = 2) => x.toFixed(digits);
console.log(`Store writes on ${cpus().length} × ${cpus()[0]?.model.trim() ?? 'CPU'}, ${seconds} s per row of moves, ${finishes} finishes; ${new Date().toISOString().slice(0, 10)}.\n`);
console.log('| store | write | writes | writes/s | p50 ms | p99 ms | PostgreSQL transactions per write |');
console.log('|---|---|---|---|---|---|---|');
for (const c of cells) console.log(`| ${c.store} | ${c.what} | ${c.n} | ${Math.round(c.perSecond)} | ${fmt(c.p50)} | ${fmt(c.p99)} | ${c.xacts === undefined ? '-' : fmt(c.xacts)} |`);
