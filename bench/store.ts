// npm run bench:store [-- --players 100000 --matches 1000000 --requests 1000 --keep]
// The leaderboard API at size: a fresh SQLite database filled through the Store (players, finished
// matches of the four kinds with their Glicko-2 ratings and records), its size on disk, then the
// real server as a child process on it and the latency of each read endpoint over HTTP on
// 127.0.0.1 (sequential keep-alive requests after a warm-up), against GET /healthz as the
// yardstick of the HTTP path alone. Prints markdown; asserts nothing.
import { existsSync, rmSync, statSync } from 'node:fs';
import { cpus } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { openDatabase } from '../server/database.ts';
import { ROOT, startServerProcess, tempDir, type ServerProcess } from '../tests/support/server-process.ts';
import { fill, KINDS, rng, type FillStats } from './store-fill.ts';

const { values } = parseArgs({
  options: {
    players: { type: 'string', default: '100000' },
    matches: { type: 'string', default: '1000000' },
    requests: { type: 'string', default: '1000' },
    warmup: { type: 'string', default: '100' },
    seed: { type: 'string', default: '20240101' },
    keep: { type: 'boolean', default: false },
  },
});
const players = Number(values.players);
const matches = Number(values.matches);
const requests = Number(values.requests);
const warmup = Number(values.warmup);
const seed = Number(values.seed);
if (![players, matches, requests, warmup, seed].every(Number.isInteger) || players < 2 || matches < 1 || requests < 1 || warmup < 0) {
  console.error('usage: npm run bench:store -- [--players 100000] [--matches 1000000] [--requests 1000] [--warmup 100] [--seed 20240101] [--keep]');
  process.exit(2);
}

/** The goal, for the endpoints it covers. */
const GOAL_MS = 5;

interface Endpoint {
  readonly name: string;
  /** Whether the goal applies (leaderboard pages, player pages, records). */
  readonly goal: boolean;
  /** The path of the i-th request. */
  readonly path: (i: number) => string;
}

interface Row {
  readonly endpoint: Endpoint;
  readonly n: number;
  readonly p50: number;
  readonly p99: number;
  readonly bad: number;
  readonly meanBytes: number;
}

/** The q-quantile of sorted xs by nearest rank. */
const quantile = (sorted: readonly number[], q: number): number => sorted[Math.max(0, Math.ceil(q * sorted.length) - 1)]!;

const mb = (bytes: number): string => (bytes / 1024 / 1024).toFixed(1);
const fmt = (x: number, digits = 2): string => (Number.isFinite(x) ? x.toFixed(digits) : '-');
const int = (x: number): string => x.toLocaleString('en-US');

/** One GET to the end of its body: ms, status and bytes. */
async function get(url: string): Promise<{ ms: number; status: number; bytes: number }> {
  const t0 = performance.now();
  const res = await fetch(url);
  const body = await res.arrayBuffer();
  return { ms: performance.now() - t0, status: res.status, bytes: body.byteLength };
}

function summary(endpoint: Endpoint, ms: number[], bad: number, bytes: number): Row {
  ms.sort((a, b) => a - b);
  return { endpoint, n: ms.length, p50: quantile(ms, 0.5), p99: quantile(ms, 0.99), bad, meanBytes: bytes / ms.length };
}

/**
 * Sequential GETs of the endpoint over one keep-alive connection, `warm` untimed, then `n` timed,
 * each followed by a GET /healthz whose time goes to `yardstick`: the yardstick sees the same
 * moments of the run (garbage collections, the machine's other work) as the endpoints do.
 */
async function measure(base: string, e: Endpoint, n: number, warm: number, yardstick: { ms: number[]; bad: number; bytes: number }): Promise<Row> {
  const ms: number[] = [];
  let bad = 0;
  let bytes = 0;
  for (let i = 0; i < warm + n; i++) {
    const a = await get(base + e.path(i));
    const h = await get(`${base}/healthz`);
    if (i < warm) continue;
    ms.push(a.ms);
    bytes += a.bytes;
    if (a.status !== 200) bad++;
    yardstick.ms.push(h.ms);
    yardstick.bytes += h.bytes;
    if (h.status !== 200) yardstick.bad++;
  }
  return summary(e, ms, bad, bytes);
}

function endpoints(stats: FillStats, r: () => number): Endpoint[] {
  const [p0, p1] = stats.playerIds;
  const [m0, m1] = stats.matchIds;
  const anyPlayer = () => p0 + Math.floor(r() * (p1 - p0 + 1));
  const busy = (i: number) => stats.busiest[i % stats.busiest.length]!;
  const kind = () => KINDS[Math.floor(r() * KINDS.length)]!;
  /** A page's offset (a multiple of 20) from 0 to `max`. */
  const page = (max: number) => 20 * Math.floor((r() * (max + 20)) / 20);
  const deepest = Math.max(0, Math.min(10_000, Math.min(...Object.values(stats.ranked)) - 20));
  const deepestRecord = (k: string) => Math.max(0, Math.min(10_000, (stats.records[k] ?? 0) - 20));
  return [
    { name: 'leaderboard, first page (the 4 kinds in turn)', goal: true, path: (i) => `/api/leaderboard?kind=${KINDS[i % KINDS.length]}` },
    { name: `leaderboard, random page (offset 0-${int(deepest)}, random kind)`, goal: true, path: () => `/api/leaderboard?kind=${kind()}&offset=${page(deepest)}` },
    ...(['snooker', 'nineball', 'threecushion'] as const).map((k) => ({ name: `records, ${k}, first page`, goal: true, path: () => `/api/records?kind=${k}` })),
    ...(['snooker', 'nineball', 'threecushion'] as const).map((k) => ({
      name: `records, ${k}, random page (offset 0-${int(deepestRecord(k))})`,
      goal: true,
      path: () => `/api/records?kind=${k}&offset=${page(deepestRecord(k))}`,
    })),
    { name: 'player page, random player', goal: true, path: () => `/api/players/${anyPlayer()}` },
    { name: `player page, the ${stats.busiest.length} busiest players`, goal: true, path: (i) => `/api/players/${busy(i)}` },
    { name: 'matches of a player, random player', goal: false, path: () => `/api/matches?player=${anyPlayer()}` },
    { name: `matches of a player, the ${stats.busiest.length} busiest players`, goal: false, path: (i) => `/api/matches?player=${busy(i)}` },
    { name: 'matches of a kind, first page (the 4 kinds in turn)', goal: false, path: (i) => `/api/matches?kind=${KINDS[i % KINDS.length]}` },
    { name: 'matches, all, first page', goal: false, path: () => '/api/matches' },
    { name: 'match by id, random match', goal: false, path: () => `/api/matches/${m0 + Math.floor(r() * (m1 - m0 + 1))}` },
  ];
}

function table(yardstick: Row, rows: readonly Row[]): string {
  const lines = ['| endpoint | requests | p50 ms | p99 ms | p99 minus healthz p99 |', '|---|---|---|---|---|'];
  lines.push(`| GET /healthz (the yardstick: one after each request below) | ${yardstick.n} | ${fmt(yardstick.p50)} | ${fmt(yardstick.p99)} | - |`);
  for (const { endpoint: e, n, p50, p99 } of rows) {
    const miss = e.goal && p99 >= GOAL_MS ? ' **(misses the goal)**' : '';
    lines.push(`| ${e.name}${e.goal ? ' \\*' : ''} | ${n} | ${fmt(p50)} | ${fmt(p99)}${miss} | ${fmt(p99 - yardstick.p99)} |`);
  }
  return lines.join('\n');
}

const dir = tempDir('baize-bench-store-');
const dbPath = join(dir, 'bench.db');
let server: ServerProcess | undefined;
let stopping: Promise<void> | undefined;
/** Stops the server and removes the database unless --keep: at the end, on error and on Ctrl-C. */
function shutDown(): Promise<void> {
  stopping ??= (async () => {
    await server?.stop();
    if (!values.keep) rmSync(dir, { recursive: true, force: true });
  })();
  return stopping;
}
process.once('SIGINT', () => void shutDown().then(() => process.exit(130)));
process.once('SIGTERM', () => void shutDown().then(() => process.exit(143)));

try {
  // 1. The fill, through the store, on a database the migrations made.
  console.error(`bench:store: filling ${dbPath} with ${int(players)} players and ${int(matches)} matches ...`);
  const t0 = performance.now();
  const { db } = openDatabase(dbPath, join(ROOT, 'migrations'));
  let stats: FillStats;
  try {
    // This connection only, for the fill's speed (the server's own connection is left as it is):
    // a page cache that holds the indexes being written, and the journals of the store's nested
    // transactions (savepoints inside the fill's batches) in memory rather than in temporary files.
    db.pragma('cache_size = -524288'); // KiB: 512 MiB
    db.pragma('temp_store = MEMORY');
    stats = fill(db, { players, matches, seed, progress: (line) => console.error(`bench:store: ${line}`) });
    // 2. Its size on disk once the WAL is checkpointed into the main file.
    db.pragma('wal_checkpoint(TRUNCATE)');
  } finally {
    db.close();
  }
  const fillSeconds = (performance.now() - t0) / 1000;
  const size = (path: string) => (existsSync(path) ? statSync(path).size : 0);
  const mainBytes = size(dbPath);
  const walBytes = size(`${dbPath}-wal`);

  // 3. The server on it, and each endpoint's latency.
  console.error('bench:store: starting the server ...');
  // The fill's players signed up on its own clock, long ago: none is pruned as an idle guest.
  server = await startServerProcess({ BAIZE_DB: dbPath, BAIZE_GUEST_KEEP_DAYS: '36500' });
  const r = rng(seed ^ 0x5eed);
  const rows: Row[] = [];
  const health = { ms: [] as number[], bad: 0, bytes: 0 };
  for (const e of endpoints(stats, r)) {
    console.error(`bench:store: ${e.name} ...`);
    rows.push(await measure(server.url, e, requests, warmup, health));
    if (server.child.exitCode !== null) throw new Error(`the server exited with ${server.child.exitCode}:\n${server.stderr().slice(-2000)}`);
  }
  const yardstick = summary({ name: 'GET /healthz', goal: false, path: () => '/healthz' }, health.ms, health.bad, health.bytes);

  const q = stats.matchesPerPlayer;
  console.log(`# bench:store (${new Date().toISOString().slice(0, 10)}, Node ${process.version}, ${cpus().length} cores)\n`);
  console.log('## The fill, through the Store\n');
  console.log(
    `${int(stats.players)} players, ${int(stats.matches)} finished matches (${int(stats.rated)} rated) in ${stats.rooms} rooms: ` +
      `**${fmt(fillSeconds, 1)} s** in all (players ${fmt(stats.playersSeconds, 1)} s, matches ${fmt(stats.matchesSeconds, 1)} s, ` +
      `${int(Math.round(stats.matches / stats.matchesSeconds))} matches a second).\n`,
  );
  console.log(
    `- matches per player: median ${q.median}, p90 ${q.p90}, p99 ${q.p99}, max ${int(q.max)}; ${int(stats.idlePlayers)} players never finished one\n` +
      `- players on the leaderboard (established: RD under 110): ${KINDS.map((k) => `${k} ${int(stats.ranked[k])}`).join(', ')}; with a rating: ${KINDS.map((k) => `${k} ${int(stats.ratedPlayers[k])}`).join(', ')}\n` +
      `- records: ${Object.entries(stats.records)
        .map(([k, v]) => `${k} ${int(v)}`)
        .join(', ')} (snooker breaks, nine-ball break-and-runs, three-cushion runs: one per player and match at most)\n` +
      '- no match has actions (match_actions is empty): the replays are not part of this data\n',
  );
  console.log('## Size on disk after a checkpoint\n');
  console.log(`main file ${mb(mainBytes)} MB + WAL ${mb(walBytes)} MB = **${mb(mainBytes + walBytes)} MB**\n`);
  console.log(`## Latency over HTTP (goal: p99 under ${GOAL_MS} ms for leaderboard pages, player pages and records at this size)\n`);
  console.log(`Sequential GETs with fetch from this process over a keep-alive connection to 127.0.0.1, ${warmup} untimed first, each followed by a GET /healthz; time to the end of the body. \\* = the goal applies.\n`);
  console.log(table(yardstick, rows));
  const notes = [yardstick, ...rows].filter((row) => row.bad > 0).map((row) => `- ${row.endpoint.name}: ${row.bad} answers were not 200`);
  notes.push(`- bytes a response on average: ${[yardstick, ...rows].map((row) => `${row.endpoint.name} ${int(Math.round(row.meanBytes))}`).join('; ')}`);
  console.log(`\n${notes.join('\n')}`);
  const log = server.stderr().trim();
  if (log) console.log(`\nserver stderr (last lines):\n\n    ${log.split('\n').slice(-5).join('\n    ')}`);
  if (values.keep) console.log(`\nkept: ${dbPath}`);
} catch (err) {
  console.error(`bench:store: ${err instanceof Error ? (err.stack ?? err.message) : String(err)}`);
  process.exitCode = 1;
} finally {
  await shutDown();
}
