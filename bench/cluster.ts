// npm run bench:cluster [-- --levels 100,300,1000 --seconds 20 --think-ms 3000 --failovers 3]
// The multi-process mode under load, side by side with the embedded default in the same run: one
// process on SQLite (the yardstick), then one and two processes over Redis and PostgreSQL (both
// started here on 127.0.0.1, PostgreSQL with fsync on). Quick bots from a separate process play
// mixed games, each room's two players on two different processes when there are two. For each
// level: shots/s, the shot round trip (p50, p99), errors, the servers' CPU, and per shot the
// Redis commands (publishes among them) and PostgreSQL transactions. Then kill -9 of a room's
// owner, timed to the first shot the survivor accepts. Prints markdown tables; asserts nothing.
import { cpus } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import pg from 'pg';
import type { Summary } from '../bots/summary.ts';
import { connectRedis, type RedisClient } from '../server/cluster/index.ts';
import { ask, connect, playTurn, until, wsUrl, type Seat } from '../tests/support/game-clients.ts';
import { startPostgres, type PostgresServer } from '../tests/support/postgres.ts';
import { startRedis, type RedisServer } from '../tests/support/redis.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../tests/support/server-process.ts';
import { runBots } from './server-bots.ts';
import { ProcSampler } from './server-proc.ts';

const { values } = parseArgs({
  options: {
    levels: { type: 'string', default: '100,300,1000' },
    seconds: { type: 'string', default: '20' },
    'think-ms': { type: 'string', default: '3000' },
    failovers: { type: 'string', default: '3' },
  },
});
const levels = values.levels.split(',').map(Number);
const seconds = Number(values.seconds);
const thinkMs = Number(values['think-ms']);
const failovers = Number(values.failovers);
if (levels.some((n) => !Number.isInteger(n) || n < 1) || !(seconds > 0) || !(thinkMs >= 0) || !Number.isInteger(failovers) || failovers < 0) {
  console.error('usage: npm run bench:cluster -- [--levels 100,300,1000] [--seconds 20] [--think-ms 3000] [--failovers 3]');
  process.exit(2);
}

/** p99 shot round trip under which a level counts as served. */
const P99_GOAL_MS = 50;

interface Row {
  readonly setup: string;
  readonly s: Summary;
  readonly cpuPercent: number;
  readonly redisPerShot: number | null;
  readonly publishesPerShot: number | null;
  readonly pgTxPerShot: number | null;
}

const fmt = (x: number | null, digits = 1): string => (x === null || !Number.isFinite(x) ? '-' : x.toFixed(digits));
const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

async function redisCounts(c: RedisClient): Promise<{ commands: number; publishes: number }> {
  const stats = String(await c.sendCommand(['INFO', 'stats']));
  const commandStats = String(await c.sendCommand(['INFO', 'commandstats']));
  const commands = Number(/total_commands_processed:(\d+)/.exec(stats)?.[1] ?? NaN);
  const publishes = Number(/cmdstat_publish:calls=(\d+)/.exec(commandStats)?.[1] ?? 0);
  return { commands, publishes };
}

async function pgCommits(url: string): Promise<number> {
  const c = new pg.Client({ connectionString: url });
  await c.connect();
  try {
    const r = await c.query<{ n: string }>('SELECT xact_commit AS n FROM pg_stat_database WHERE datname = current_database()');
    return Number(r.rows[0]!.n);
  } finally {
    await c.end();
  }
}

let redis: RedisServer | undefined;
let db: PostgresServer | undefined;
let monitor: RedisClient | undefined;
const running: ServerProcess[] = [];

async function stopAll(signal: NodeJS.Signals = 'SIGTERM'): Promise<void> {
  await Promise.all(running.splice(0).map((p) => p.stop(signal)));
}

/** One set-up at every level: its processes started fresh, stopped after. */
async function measure(setup: string, env: (i: number) => Record<string, string>, processes: number, dbUrl?: string): Promise<Row[]> {
  const rows: Row[] = [];
  for (const rooms of levels) {
    for (let i = 0; i < processes; i++) running.push(await startServerProcess(env(i)));
    const urls = running.map((p) => wsUrl(p.url));
    console.error(`bench:cluster: ${setup}, ${rooms} rooms for ${seconds} s ...`);
    const samplers = running.map((p) => new ProcSampler(p.child.pid!));
    const r0 = monitor && processes > 0 && dbUrl ? await redisCounts(monitor) : undefined;
    const t0 = dbUrl ? await pgCommits(dbUrl) : undefined;
    const run = await runBots({ url: urls.join(','), rooms, seconds, thinkMs, kind: 'mixed' }, () => samplers.forEach((x) => x.sample()));
    const r1 = r0 && monitor ? await redisCounts(monitor) : undefined;
    const t1 = dbUrl ? await pgCommits(dbUrl) : undefined;
    samplers.forEach((x) => x.stop());
    const from = run.at - run.summary.seconds * 1000;
    const cpuPercent = samplers.reduce((sum, x) => sum + x.window(from, run.at).cpuPercent, 0);
    // Counted over the whole run (set-up and leaving too), so a little above play alone.
    const shots = run.summary.shots;
    rows.push({
      setup,
      s: run.summary,
      cpuPercent,
      redisPerShot: r0 && r1 && shots > 0 ? (r1.commands - r0.commands) / shots : null,
      publishesPerShot: r0 && r1 && shots > 0 ? (r1.publishes - r0.publishes) / shots : null,
      pgTxPerShot: t0 !== undefined && t1 !== undefined && shots > 0 ? (t1 - t0) / shots : null,
    });
    console.error(JSON.stringify(run.summary));
    for (const p of running) if (p.child.exitCode !== null) throw new Error(`a server exited with ${p.child.exitCode}:\n${p.stderr().slice(-2000)}`);
    await stopAll();
    await monitor?.sendCommand(['FLUSHALL']);
  }
  return rows;
}

/** kill -9 of a room's owner between two shots; ms until the survivor accepts the next shot. */
async function failover(dbUrl: string, env: (i: number) => Record<string, string>): Promise<number> {
  for (let i = 0; i < 2; i++) running.push(await startServerProcess(env(i)));
  const [owner, survivor] = running as [ServerProcess, ServerProcess];
  const seats: Seat[] = [];
  try {
    const maker = await connect(wsUrl(owner.url), { name: `Fo-${Math.random().toString(36).slice(2, 8)}` });
    seats.push(maker);
    const created = await ask(maker, { type: 'create', kind: 'nineball', raceTo: 5 });
    if (created.type !== 'room') throw new Error(JSON.stringify(created));
    const room = created.room.id;
    const other = await connect(wsUrl(survivor.url), { name: `Fo-${Math.random().toString(36).slice(2, 8)}` });
    seats.push(other);
    await ask(other, { type: 'join', room });
    await until(other, room, (r) => r.status === 'playing');
    // The maker comes back through the survivor, so that both players stay.
    const back = await connect(wsUrl(survivor.url), { token: maker.token });
    seats.push(back);
    await until(back, room, (r) => r.stateId === other.rooms.get(room)!.stateId);
    const onTurn = other.rooms.get(room)!.game!.turn === other.player.id ? other : back;
    const killed = performance.now();
    await owner.stop('SIGKILL');
    for (;;) {
      try {
        await playTurn(onTurn, room);
        return performance.now() - killed;
      } catch (err) {
        if (!String(err).includes('"unavailable"') || performance.now() - killed > 30_000) throw err;
        await sleep(50);
      }
    }
  } finally {
    await Promise.all(seats.map((s) => s.client.close(200)));
    await stopAll('SIGKILL');
    await monitor?.sendCommand(['FLUSHALL']);
    void dbUrl;
  }
}

function table(rows: readonly Row[]): string {
  const lines = [
    '| set-up | rooms | shots/s | round trip p50 ms | p99 ms | errors | servers CPU % | Redis commands / shot | publishes / shot | PostgreSQL commits / shot |',
    '|---|---|---|---|---|---|---|---|---|---|',
  ];
  for (const { setup, s, cpuPercent, redisPerShot, publishesPerShot, pgTxPerShot } of rows) {
    const perSecond = s.seconds > 0 ? s.shots / s.seconds : NaN;
    lines.push(`| ${setup} | ${s.rooms} | ${fmt(perSecond)} | ${fmt(s.rttMs.p50)} | ${fmt(s.rttMs.p99)} | ${s.errors} | ${fmt(cpuPercent, 0)} | ${fmt(redisPerShot)} | ${fmt(publishesPerShot)} | ${fmt(pgTxPerShot)} |`);
  }
  return lines.join('\n');
}

/** The most rooms (and their shots/s) served at a p99 under the goal, per set-up. */
function served(rows: readonly Row[]): string {
  const lines = [`| set-up | most rooms measured with p99 < ${P99_GOAL_MS} ms | shots/s there |`, '|---|---|---|'];
  for (const setup of [...new Set(rows.map((r) => r.setup))]) {
    const ok = rows.filter((r) => r.setup === setup && r.s.rttMs.p99 !== null && r.s.rttMs.p99 < P99_GOAL_MS && r.s.errors === 0);
    const best = ok.sort((a, b) => b.s.rooms - a.s.rooms)[0];
    lines.push(`| ${setup} | ${best ? best.s.rooms : 'none'} | ${best ? fmt(best.s.shots / best.s.seconds) : '-'} |`);
  }
  return lines.join('\n');
}

process.once('SIGINT', () => void stopAll('SIGKILL').then(() => process.exit(130)));
try {
  [redis, db] = await Promise.all([startRedis(), startPostgres({ durable: true })]);
  monitor = await connectRedis(redis.url, 'bench');
  const dir = tempDir('baize-bench-cluster-');
  const sqlite = () => ({ BAIZE_DB: join(dir, `sqlite-${Date.now()}.db`) });
  const cluster = (dbUrl: string) => (i: number) => ({ BAIZE_DATABASE_URL: dbUrl, BAIZE_REDIS_URL: redis!.url, BAIZE_PROCESS_ID: `b${i + 1}` });
  const rows: Row[] = [];
  rows.push(...(await measure('1 process, SQLite', sqlite, 1)));
  const one = await db.database('one');
  rows.push(...(await measure('1 process, Redis + PostgreSQL', cluster(one), 1, one)));
  const two = await db.database('two');
  rows.push(...(await measure('2 processes, Redis + PostgreSQL', cluster(two), 2, two)));
  const times: number[] = [];
  const fo = await db.database('failover');
  for (let i = 0; i < failovers; i++) times.push(await failover(fo, cluster(fo)));

  console.log(`# bench:cluster (${new Date().toISOString().slice(0, 10)}, Node ${process.version}, ${cpus().length} cores)\n`);
  console.log(`Quick bots in a separate process, mixed games, ${seconds} s a level, ${thinkMs} ms thinking before each shot; with two processes each room's players are on different ones. Everything (servers, bots, Redis, PostgreSQL with fsync on) shares this machine.\n`);
  console.log(table(rows));
  console.log('');
  console.log(served(rows));
  if (times.length > 0) {
    const sorted = [...times].sort((a, b) => a - b);
    console.log(`\nFailover (kill -9 of a room's owner, 2 processes): first shot accepted by the survivor after ${sorted.map((t) => (t / 1000).toFixed(1)).join(', ')} s (median ${(sorted[Math.floor(sorted.length / 2)]! / 1000).toFixed(1)} s).`);
  }
} catch (err) {
  console.error(`bench:cluster: ${err instanceof Error ? (err.stack ?? err.message) : String(err)}`);
  process.exitCode = 1;
} finally {
  await stopAll('SIGKILL');
  monitor?.destroy();
  await Promise.all([redis?.stop(), db?.stop()]);
}
