// Rate limits and the server's own stalls (issue 36, finding 11): the server process is stopped
// (SIGSTOP, as a long pause of the process would) while well-behaved clients keep sending within
// the limit; when it runs again their frames arrive together, and none of them is closed for it.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { RATE_BURST, RATE_PER_SECOND } from '../../shared/protocol/index.ts';
import { wsUrl } from '../support/game-clients.ts';
import { endedWithin, rawSocket, receivedWithin, type RawSocket } from '../support/raw-sockets.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

let server: ServerProcess | undefined;
const sockets: RawSocket[] = [];
afterEach(async () => {
  if (server?.child.exitCode === null) server.child.kill('SIGCONT');
  for (const s of sockets.splice(0)) s.ws.terminate();
  await server?.stop('SIGKILL');
  server = undefined;
});

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

describe('rate limits after a stall of the server', () => {
  it('closes none of 20 tabs sending 12 a second through a 5 s stop of the server', async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db') });
    const url = wsUrl(server.url);
    for (let i = 0; i < 20; i++) {
      const s = await rawSocket(url);
      s.send({ type: 'hello', id: 'h' });
      await receivedWithin(s, (m) => m.type === 'welcome');
      sockets.push(s);
    }
    const perSecond = 12;
    // 12 a second for 5 s is 60 frames at once afterwards: more than the burst of 40, well
    // within the rate of 20 a second the limit allows.
    expect(perSecond).toBeLessThan(RATE_PER_SECOND);
    expect(perSecond * 5).toBeGreaterThan(RATE_BURST);
    let n = 0;
    const timer = setInterval(() => {
      for (const s of sockets) if (s.ws.readyState === s.ws.OPEN) s.send({ type: 'leave', room: '-', id: n });
      n++;
    }, 1000 / perSecond);
    try {
      await sleep(1000);
      server.child.kill('SIGSTOP');
      await sleep(5000);
      server.child.kill('SIGCONT');
      await sleep(2000);
    } finally {
      clearInterval(timer);
    }
    const ends = await Promise.all(sockets.map((s) => endedWithin(s, 500)));
    expect(ends.filter((e) => e !== 'open')).toEqual([]);
    // Every frame was answered (each is refused as no-room: the cheapest command there is).
    for (const s of sockets) {
      const last = n - 1;
      await receivedWithin(s, (m) => m.re === last);
      expect(s.received.filter((m) => m.code === 'no-room')).toHaveLength(n);
    }
  }, 30_000);
});
