// The attacks of issue 36's findings 4, 5 and 9, run by bench/attacks.ts in a process of their own so
// that the measurements are not taken in the attackers' event loop. Each runs for `seconds`, then
// prints one JSON line of what it saw and exits.
//   idle:  2,000 sockets from 127.0.0.1 that never say hello; every one the server closes is opened
//          again (100 ms later), as a persistent attacker would.
//   flood: one player's 1,000 tabs that never read, seated in a game in play, and 60 more sockets
//          switching watch/leave on that room at 18 frames a second each, under the rate limit.
//   practice: 8 players asking for a practice seed and posting a scoring snooker break with it,
//          again and again, as fast as the answers come.
import type { Socket } from 'node:net';
import { parseArgs } from 'node:util';
import { WebSocket } from 'ws';
import { snookerBreak } from '../tests/support/snooker-break.ts';

const { values } = parseArgs({
  options: { attack: { type: 'string' }, url: { type: 'string' }, seconds: { type: 'string', default: '20' } },
});
const url = values.url!;
const seconds = Number(values.seconds);
const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

const stats = { opened: 0, refused: 0, closedByServer: 0, welcomed: 0, openAtEnd: 0, errors: 0 };
const all = new Set<WebSocket>();

/** Opens a socket; resolves with it once open, or undefined if the server refused the connection. */
function open(): Promise<WebSocket | undefined> {
  return new Promise((res) => {
    const ws = new WebSocket(url, { handshakeTimeout: 5000 });
    ws.on('error', () => {
      stats.errors++;
      res(undefined);
    });
    ws.once('open', () => {
      stats.opened++;
      all.add(ws);
      ws.once('close', (code) => {
        all.delete(ws);
        if (code === 1008) stats.refused++;
        else stats.closedByServer++;
      });
      res(ws);
    });
  });
}

/** Sends and waits for the answer carrying `re` (the socket reads). */
function request(ws: WebSocket, msg: object, id: string): Promise<Record<string, unknown>> {
  return new Promise((res, rej) => {
    const onMessage = (d: Buffer) => {
      const m = JSON.parse(String(d)) as Record<string, unknown>;
      if (m.re !== id) return;
      ws.off('message', onMessage);
      res(m);
    };
    ws.on('message', onMessage);
    ws.once('close', () => rej(new Error('closed')));
    ws.send(JSON.stringify({ ...msg, id }));
  });
}

async function idle(until: number): Promise<void> {
  const keep = async (): Promise<void> => {
    while (Date.now() < until) {
      const ws = await open();
      if (ws) await Promise.race([new Promise((r) => ws.once('close', r)), sleep(until - Date.now())]);
      await sleep(100);
    }
  };
  await Promise.all(Array.from({ length: 2000 }, keep));
}

async function flood(until: number): Promise<void> {
  const first = await open();
  if (!first) throw new Error('could not connect');
  const welcome = await request(first, { type: 'hello' }, 'h');
  const token = welcome.token as string;
  const created = await request(first, { type: 'create', kind: 'snooker' }, 'c');
  const room = (created.room as { id: string }).id;
  const other = (await open())!;
  await request(other, { type: 'hello' }, 'h');
  await request(other, { type: 'join', room }, 'j');
  // The tabs: hello with the player's token, then never read again.
  await Promise.all(
    Array.from({ length: 1000 }, async () => {
      const ws = await open();
      if (!ws) return;
      const m = await request(ws, { type: 'hello', token }, 'h').catch(() => undefined);
      if (m?.type === 'welcome') stats.welcomed++;
      (ws as unknown as { _socket: Socket })._socket.pause();
    }),
  );
  const churn = async (): Promise<void> => {
    const ws = await open();
    if (!ws) return;
    const m = await request(ws, { type: 'hello' }, 'h').catch(() => undefined);
    if (m?.type !== 'welcome') return;
    for (let i = 0; Date.now() < until && ws.readyState === ws.OPEN; i++) {
      ws.send(JSON.stringify({ type: i % 2 === 0 ? 'watch' : 'leave', room }));
      await sleep(1000 / 18);
    }
  };
  await Promise.all(Array.from({ length: 60 }, churn));
}


async function practice(until: number): Promise<void> {
  const http = url.replace(/^ws/, 'http').replace(/\/ws$/, '');
  const shots = snookerBreak('bench', 30);
  const counts: Record<string, number> = {};
  const post = async (path: string, body: unknown) => {
    const res = await fetch(`${http}${path}`, { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(body) });
    const json = (await res.json()) as { seed?: number };
    counts[`${path} ${res.status}`] = (counts[`${path} ${res.status}`] ?? 0) + 1;
    return { status: res.status, json };
  };
  await Promise.all(
    Array.from({ length: 8 }, async () => {
      const ws = await open();
      if (!ws) return;
      const token = (await request(ws, { type: 'hello' }, 'h')).token as string;
      while (Date.now() < until) {
        const start = await post('/api/practice/start', { token, kind: 'snooker' });
        if (start.status === 200) await post('/api/practice', { token, kind: 'snooker', seed: start.json.seed, shots });
      }
    }),
  );
  Object.assign(stats, { shots: shots.length, ...counts });
}

const until = Date.now() + seconds * 1000;
if (values.attack === 'idle') await idle(until);
else if (values.attack === 'flood') await flood(until);
else if (values.attack === 'practice') await practice(until);
else throw new Error(`unknown attack ${values.attack}`);
await sleep(Math.max(0, until - Date.now()));
stats.openAtEnd = [...all].filter((ws) => ws.readyState === ws.OPEN).length;
console.log(JSON.stringify(stats));
for (const ws of all) ws.terminate();
process.exit(0);
