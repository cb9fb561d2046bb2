// npm run bench:attacks [-- --seconds 20 --scenarios none,idle,flood,flood-uncapped,practice]
// The attacks of issue 36's findings 4, 5 and 9 on the real server (a child process on 127.0.0.1,
// a temporary database), each from a process of its own (bench/attackers.ts), while this process
// measures what an honest user meets: GET /healthz ten times a second (2 s timeout), and once a
// second a player from another address (127.0.0.3) who connects, says hello and asks for the
// lobby. The server runs with its default limits, except `flood-uncapped`, which lifts the caps
// per address and per player to show what the backpressure and coalescing do alone. Prints a
// markdown table; asserts nothing. Bounded: one server and one attack at a time, `seconds` each.
import { spawn } from 'node:child_process';
import { rmSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { parseArgs } from 'node:util';
import { WebSocket } from 'ws';
import { percentile } from '../bots/summary.ts';
import { startServerProcess, tempDir } from '../tests/support/server-process.ts';
import { ProcSampler, rssMb } from './server-proc.ts';

const ROOT = resolve(import.meta.dirname, '..');
const { values } = parseArgs({
  options: {
    seconds: { type: 'string', default: '20' },
    scenarios: { type: 'string', default: 'none,idle,flood,flood-uncapped,practice' },
  },
});
const seconds = Number(values.seconds);
const SCENARIOS: Record<string, { attack?: string; env: Record<string, string>; what: string }> = {
  none: { env: { BAIZE_MAX_SOCKETS_PER_ADDRESS: '50' }, what: 'no attack' },
  idle: { attack: 'idle', env: { BAIZE_MAX_SOCKETS_PER_ADDRESS: '50' }, what: '2,000 idle sockets' },
  flood: { attack: 'flood', env: { BAIZE_MAX_SOCKETS_PER_ADDRESS: '50' }, what: '1,000 tabs not reading + 60 churning' },
  'flood-uncapped': {
    attack: 'flood',
    env: { BAIZE_MAX_SOCKETS_PER_ADDRESS: '100000', BAIZE_MAX_TABS_PER_PLAYER: '100000' },
    what: 'the same, caps lifted',
  },
  practice: { attack: 'practice', env: { BAIZE_MAX_SOCKETS_PER_ADDRESS: '50' }, what: '8 players posting practice runs non-stop' },
};
const chosen = values.scenarios.split(',');
if (!(seconds > 0) || chosen.some((s) => !(s in SCENARIOS))) {
  console.error(`usage: npm run bench:attacks -- [--seconds 20] [--scenarios ${Object.keys(SCENARIOS).join(',')}]`);
  process.exit(2);
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/** GET /healthz every 100 ms until `until`: each probe's time, or null when it failed or took over 2 s. */
async function probeHealth(base: string, until: number): Promise<(number | null)[]> {
  const out: Promise<number | null>[] = [];
  while (Date.now() < until) {
    const t0 = performance.now();
    out.push(
      fetch(`${base}/healthz`, { signal: AbortSignal.timeout(2000) }).then(
        async (r) => {
          await r.arrayBuffer();
          return r.ok ? performance.now() - t0 : null;
        },
        () => null,
      ),
    );
    await sleep(100);
  }
  return Promise.all(out);
}

/** A player from 127.0.0.3: connect, hello, lobby; the time it took, or null when refused or over 5 s. */
function player(wsUrl: string): Promise<number | null> {
  return new Promise((res) => {
    const t0 = performance.now();
    const ws = new WebSocket(wsUrl, { localAddress: '127.0.0.3', handshakeTimeout: 5000 });
    let settled = false;
    const done = (v: number | null) => {
      if (settled) return;
      settled = true;
      clearTimeout(timer);
      ws.terminate();
      res(v);
    };
    const timer = setTimeout(() => done(null), 5000);
    ws.on('error', () => done(null));
    ws.on('close', () => done(null));
    ws.on('open', () => ws.send(JSON.stringify({ type: 'hello', id: 1 })));
    ws.on('message', (d) => {
      const m = JSON.parse(String(d)) as { type: string; re?: unknown };
      if (m.re === 1) (m.type === 'welcome' ? ws.send(JSON.stringify({ type: 'lobby', id: 2, watch: false })) : done(null));
      if (m.re === 2) done(m.type === 'lobby' ? performance.now() - t0 : null);
    });
  });
}

async function probePlayers(wsUrl: string, until: number): Promise<(number | null)[]> {
  const out: Promise<number | null>[] = [];
  while (Date.now() < until) {
    out.push(player(wsUrl));
    await sleep(1000);
  }
  return Promise.all(out);
}

function runAttack(attack: string, wsUrl: string): { done: Promise<string> } {
  const child = spawn(process.execPath, ['--import', 'tsx', 'bench/attackers.ts', '--attack', attack, '--url', wsUrl, '--seconds', String(seconds)], {
    cwd: ROOT,
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  let out = '';
  child.stdout.setEncoding('utf8').on('data', (d: string) => (out += d));
  const kill = setTimeout(() => child.kill('SIGKILL'), (seconds + 60) * 1000);
  return {
    done: new Promise((res) =>
      child.once('exit', () => {
        clearTimeout(kill);
        res(out.trim().split('\n').at(-1) ?? '');
      }),
    ),
  };
}

const fmt = (x: number | null) => (x === null ? '-' : x.toFixed(1));
const rows: string[] = [];
for (const name of chosen) {
  const scenario = SCENARIOS[name]!;
  const dir = tempDir('baize-attacks-');
  const server = await startServerProcess({ BAIZE_DB: join(dir, 'bench.db'), ...scenario.env });
  try {
    const wsUrl = `${server.url.replace(/^http/, 'ws')}/ws`;
    const pid = server.child.pid!;
    const before = rssMb(pid);
    const sampler = new ProcSampler(pid);
    console.error(`bench:attacks: ${name} for ${seconds} s ...`);
    const attack = scenario.attack ? runAttack(scenario.attack, wsUrl) : undefined;
    const until = Date.now() + seconds * 1000;
    const [health, players] = await Promise.all([probeHealth(server.url, until), probePlayers(wsUrl, until)]);
    const attackers = (await attack?.done) ?? '';
    await sleep(3000);
    sampler.stop();
    const after = rssMb(pid);
    const peak = Math.max(...sampler.samples.map((s) => s.rss));
    const ok = health.filter((x): x is number => x !== null);
    const okPlayers = players.filter((x): x is number => x !== null);
    rows.push(
      `| ${name} (${scenario.what}) | ${health.length - ok.length} / ${health.length} | ${fmt(percentile(ok, 50))} | ${fmt(percentile(ok, 99))} | ` +
        `${okPlayers.length} / ${players.length} | ${fmt(percentile(okPlayers, 99))} | ${before.toFixed(0)} / ${peak.toFixed(0)} / ${after.toFixed(0)} | ${attackers ? `\`${attackers}\`` : ''} |`,
    );
  } finally {
    await server.stop('SIGKILL');
    rmSync(dir, { recursive: true, force: true });
  }
}
console.log(`# bench:attacks (${new Date().toISOString().slice(0, 10)}, Node ${process.version}), ${seconds} s each\n`);
console.log('| scenario | /healthz failed | p50 ms | p99 ms | players served | player p99 ms | server RSS MB before / peak / after | attackers |');
console.log('|---|---|---|---|---|---|---|---|');
for (const r of rows) console.log(r);
