// npm run bench:server [-- --levels 10,100,1000 --seconds 35 --think-ms 3000 --kind mixed]
// The real server as a child process (ephemeral port, a temporary database) under 10, 100 and
// 1,000 rooms of quick bots from a separate process, each room shooting every few seconds. For each
// level: shots/s, the shot round trip, errors, games finished, and the server's CPU (% of one core)
// and peak RSS from /proc. Prints a markdown table; asserts nothing.
import { rmSync } from 'node:fs';
import { cpus } from 'node:os';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import type { Summary } from '../bots/summary.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../tests/support/server-process.ts';
import { runBots } from './server-bots.ts';
import { ProcSampler } from './server-proc.ts';

const { values } = parseArgs({
  options: {
    levels: { type: 'string', default: '10,100,1000' },
    seconds: { type: 'string', default: '35' },
    'think-ms': { type: 'string', default: '3000' },
    kind: { type: 'string', default: 'mixed' },
  },
});
const levels = values.levels.split(',').map(Number);
const seconds = Number(values.seconds);
const thinkMs = Number(values['think-ms']);
if (levels.some((n) => !Number.isInteger(n) || n < 1) || !(seconds > 0) || !(thinkMs >= 0)) {
  console.error('usage: npm run bench:server -- [--levels 10,100,1000] [--seconds 35] [--think-ms 3000] [--kind mixed]');
  process.exit(2);
}

interface Row {
  readonly summary: Summary;
  readonly cpuPercent: number;
  readonly rssPeakMb: number;
}

const fmt = (x: number | null, digits = 1): string => (x === null || !Number.isFinite(x) ? '-' : x.toFixed(digits));

function table(rows: readonly Row[]): string {
  const lines = [
    '| rooms | sockets | shots/s | shot round trip p50 ms | p99 ms | yardstick p50 ms | p99 ms | errors | games finished | server CPU % | server RSS MB |',
    '|---|---|---|---|---|---|---|---|---|---|---|',
  ];
  for (const { summary: s, cpuPercent, rssPeakMb } of rows) {
    const perSecond = s.seconds > 0 ? s.shots / s.seconds : NaN;
    lines.push(
      `| ${s.rooms} | ${s.sockets} | ${fmt(perSecond)} | ${fmt(s.rttMs.p50)} | ${fmt(s.rttMs.p99)} | ${fmt(s.yardstickMs.p50)} | ${fmt(s.yardstickMs.p99)} | ${s.errors} | ${s.gamesFinished} | ${fmt(cpuPercent, 0)} | ${fmt(rssPeakMb, 0)} |`,
    );
  }
  return lines.join('\n');
}

/** What the summary holds beyond the table: error codes, dropped sockets, rooms never set up. */
function notes(rows: readonly Row[]): string[] {
  const out: string[] = [];
  for (const { summary: s } of rows) {
    const extra = [];
    if (s.errors > 0) extra.push(`errors ${JSON.stringify(s.errorCodes)}`);
    if (s.disconnects > 0) extra.push(`${s.disconnects} sockets dropped by the server`);
    if (s.setupFailures > 0) extra.push(`${s.setupFailures} rooms not set up`);
    if (extra.length > 0) out.push(`- ${s.rooms} rooms: ${extra.join('; ')}`);
  }
  return out;
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

const dir = tempDir('baize-bench-');
const abort = new AbortController();
let server: ServerProcess | undefined;
let stopping: Promise<void> | undefined;
/** Stops the bots and the server and removes the database: at the end, on error and on Ctrl-C. */
function shutDown(): Promise<void> {
  stopping ??= (async () => {
    abort.abort();
    await server?.stop();
    rmSync(dir, { recursive: true, force: true });
  })();
  return stopping;
}
process.once('SIGINT', () => void shutDown().then(() => process.exit(130)));
process.once('SIGTERM', () => void shutDown().then(() => process.exit(143)));

try {
  server = await startServerProcess({ BAIZE_DB: join(dir, 'bench.db') });
  const pid = server.child.pid!;
  const url = `${server.url.replace(/^http/, 'ws')}/ws`;
  const rows: Row[] = [];
  for (const rooms of levels) {
    console.error(`bench:server: ${rooms} rooms for ${seconds} s ...`);
    const sampler = new ProcSampler(pid);
    const run = await runBots({ url, rooms, seconds, thinkMs, kind: values.kind }, () => sampler.sample(), abort.signal);
    sampler.stop();
    if (server.child.exitCode !== null) throw new Error(`the server exited with ${server.child.exitCode}:\n${server.stderr().slice(-2000)}`);
    // The window is the bots' play: from their start to their summary, not their start-up or leaving.
    rows.push({ summary: run.summary, ...sampler.window(run.at - run.summary.seconds * 1000, run.at) });
    console.error(JSON.stringify(run.summary));
    await sleep(2000); // the last level's rooms are left and closed before the next one
  }
  console.log(`# bench:server (${new Date().toISOString().slice(0, 10)}, Node ${process.version}, ${cpus().length} cores)\n`);
  console.log(`Quick bots in a separate process, ${values.kind} games, ${seconds} s a level, ${thinkMs} ms thinking before each shot.`);
  console.log('The yardstick, from the same process and under the same load: a request the server refuses at once (no simulation, no write), four a second.\n');
  console.log(table(rows));
  const extra = notes(rows);
  if (extra.length > 0) console.log(`\n${extra.join('\n')}`);
  const log = server.stderr().trim();
  if (log) console.log(`\nserver stderr (last lines):\n\n    ${log.split('\n').slice(-5).join('\n    ')}`);
} catch (err) {
  console.error(`bench:server: ${err instanceof Error ? err.message : String(err)}`);
  process.exitCode = 1;
} finally {
  await shutDown();
}
