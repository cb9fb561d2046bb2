// Issue 36, finding 9: clients hammering the practice API while /healthz is probed. Each client
// (its own player, all from 127.0.0.1) asks for a seed and posts a scoring snooker break, again and
// again, for a few seconds; the probe's latency is reported idle and under the flood.
//
//   node --import tsx bench/practice-flood.ts [clients=8] [seconds=5]
//
// It starts a server of this checkout with the default limits, or uses BAIZE_URL's (a server of
// an older checkout, which issues no seeds: the runs then carry seeds of their own).
import { join } from 'node:path';
import { chooseShot } from '../bots/strategy.ts';
import { simulate } from '../shared/physics/index.ts';
import { playShot, practiceStart, type Game, type PracticeShot } from '../shared/rules/index.ts';
import { connect, wsUrl, type Seat } from '../tests/support/game-clients.ts';
import { startServerProcess, tempDir } from '../tests/support/server-process.ts';

const CLIENTS = Number(process.argv[2] ?? 8);
const SECONDS = Number(process.argv[3] ?? 5);
const PROBE_MS = 20;

/** A snooker break from the D of up to `max` shots: a first red by a fan of headings, then the bot. */
function snookerBreak(max: number): PracticeShot[] {
  const P = 'bench';
  let game: Game = practiceStart('snooker', P, 0);
  const shots: PracticeShot[] = [];
  for (let i = 0; i < 360 && shots.length === 0; i++) {
    const shot = { ball: 'cue', heading: (i * Math.PI) / 180, speed: 5, side: 0, top: 0 };
    try {
      const next = playShot(game, { ...shot, player: P }).game;
      if (!next.verdict!.foul && next.verdict!.potted.length > 0) {
        shots.push({ shot });
        game = next;
      }
    } catch {
      // the next heading
    }
  }
  while (shots.length > 0 && shots.length < max && game.winner === null && game.turn === P) {
    const { player: _p, ...shot } = chooseShot(game, 'sound', (scene, s) => simulate(scene, s));
    shots.push({ shot });
    game = playShot(game, { ...shot, player: P }).game;
  }
  return shots;
}

function quantile(sorted: number[], q: number): number {
  return sorted.length === 0 ? NaN : sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))]!;
}

/** Probes /healthz every PROBE_MS until `stop` resolves: when each probe was sent and its latency, ms. */
async function probe(url: string, stop: Promise<void>): Promise<{ at: number; ms: number }[]> {
  const times: { at: number; ms: number }[] = [];
  let done = false;
  void stop.then(() => (done = true));
  while (!done) {
    const t = performance.now();
    const res = await fetch(`${url}/healthz`);
    await res.arrayBuffer();
    times.push({ at: t, ms: performance.now() - t });
    await new Promise((r) => setTimeout(r, PROBE_MS));
  }
  return times;
}

const sorted = (t: { ms: number }[]) => t.map((x) => x.ms).sort((a, b) => a - b);
const summary = (t: number[]) => `n=${t.length} p50=${quantile(t, 0.5).toFixed(1)} ms p99=${quantile(t, 0.99).toFixed(1)} ms max=${(t.at(-1) ?? NaN).toFixed(1)} ms`;

const own = process.env.BAIZE_URL ? null : await startServerProcess({ BAIZE_DB: join(tempDir('baize-flood-'), 'baize.db') });
const url = process.env.BAIZE_URL ?? own!.url;
const shots = snookerBreak(30);
const seats: Seat[] = [];
try {
  for (let i = 0; i < CLIENTS; i++) seats.push(await connect(wsUrl(url), { name: `Flood-${i}-${Date.now() % 100000}` }));
  const idle = sorted(await probe(url, new Promise((r) => setTimeout(r, 2000))));

  const counts = new Map<string, number>();
  const count = (what: string) => counts.set(what, (counts.get(what) ?? 0) + 1);
  const post = async (path: string, body: unknown) => {
    const res = await fetch(`${url}${path}`, { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(body) });
    const json = (await res.json()) as { seed?: number };
    count(`${path} ${res.status}`);
    return { status: res.status, json };
  };
  const begin = performance.now();
  const end = begin + SECONDS * 1000;
  const flood = Promise.all(
    seats.map(async (s) => {
      while (performance.now() < end) {
        const start = await post('/api/practice/start', { token: s.token, kind: 'snooker' });
        if (start.status === 429) continue;
        const seed = start.status === 200 ? start.json.seed! : Math.floor(Math.random() * 2 ** 32); // an old server: no seeds issued
        await post('/api/practice', { token: s.token, kind: 'snooker', seed, shots });
      }
    }),
  );
  const probes = await probe(url, flood.then(() => undefined));
  const busy = sorted(probes);
  // After the first 2 s, the buckets' bursts are spent: the sustained rate.
  const sustained = sorted(probes.filter((p) => p.at >= begin + 2000));
  console.log(`practice flood: ${CLIENTS} clients for ${SECONDS} s, a ${shots.length}-shot snooker break each post, /healthz every ${PROBE_MS} ms`);
  console.log(`  idle:  ${summary(idle)}`);
  console.log(`  flood: ${summary(busy)}`);
  console.log(`  after its first 2 s: ${summary(sustained)}`);
  console.log(`  requests: ${[...counts].sort().map(([k, n]) => `${k}: ${n}`).join(', ')}`);
} finally {
  await Promise.all(seats.map((s) => s.client.close(200)));
  await own?.stop('SIGKILL');
}
