// Limits on connections (issue 36, finding 4), against a real server process over real sockets:
// sockets per address, tabs per player, a deadline for hello, deadlines for slow HTTP requests.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { endedWithin, rawSocket, receivedWithin, refusedUpgrade, trickle, type RawSocket } from '../support/raw-sockets.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';
import { wsUrl } from '../support/game-clients.ts';

let server: ServerProcess | undefined;
const sockets: RawSocket[] = [];
afterEach(async () => {
  for (const s of sockets.splice(0)) s.ws.terminate();
  await server?.stop('SIGKILL');
  server = undefined;
});

async function start(env: Record<string, string>): Promise<string> {
  server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db'), ...env });
  return wsUrl(server.url);
}

async function open(url: string): Promise<RawSocket> {
  const s = await rawSocket(url);
  sockets.push(s);
  return s;
}

describe('limits on connections', () => {
  it('refuses a socket over the cap per address at the upgrade (429); a freed place is taken again', async () => {
    const url = await start({ BAIZE_MAX_SOCKETS_PER_ADDRESS: '5' });
    const five = await Promise.all([1, 2, 3, 4, 5].map(() => open(url)));
    expect(await refusedUpgrade(url)).toEqual({ status: 429, retryAfter: '10', body: 'too many connections from your address (at most 5)' });
    for (const s of five) expect(await endedWithin(s, 0)).toBe('open');
    five[0]!.ws.close();
    await five[0]!.ended;
    const again = await open(url);
    again.send({ type: 'hello', id: 1 });
    expect(await receivedWithin(again, (m) => m.re === 1)).toMatchObject({ type: 'welcome' });
    expect(await endedWithin(again, 300)).toBe('open');
  });

  it('closes a socket that has not said hello by the deadline (1008); a welcomed one stays', async () => {
    const url = await start({ BAIZE_HELLO_TIMEOUT_S: '0.5' });
    const silent = await open(url);
    const polite = await open(url);
    polite.send({ type: 'hello', id: 1 });
    await receivedWithin(polite, (m) => m.type === 'welcome');
    expect(await endedWithin(silent, 5000)).toEqual({ code: 1008, reason: 'say hello within 0.5 s' });
    expect(await endedWithin(polite, 1000)).toBe('open');
  });

  it('refuses one tab too many of a player with too-many-tabs; a closed tab frees a place', async () => {
    const url = await start({ BAIZE_MAX_TABS_PER_PLAYER: '3' });
    const first = await open(url);
    first.send({ type: 'hello', id: 'h' });
    const { token } = (await receivedWithin(first, (m) => m.type === 'welcome')) as unknown as { token: string };
    const tabs = [first];
    for (let i = 0; i < 2; i++) {
      const tab = await open(url);
      tab.send({ type: 'hello', id: 'h', token });
      await receivedWithin(tab, (m) => m.type === 'welcome');
      tabs.push(tab);
    }
    const extra = await open(url);
    extra.send({ type: 'hello', id: 'h', token });
    const refused = await receivedWithin(extra, (m) => m.re === 'h');
    expect(refused).toMatchObject({ type: 'error', code: 'too-many-tabs' });
    expect(refused.message).toContain('at most 3 tabs');
    // The socket stays, unwelcomed, and may say hello again once another tab has closed.
    tabs[0]!.ws.close();
    await tabs[0]!.ended;
    // The server hears of the close a moment after the client: ask until it has.
    for (let i = 0; i < 20 && !extra.received.some((m) => m.type === 'welcome'); i++) {
      extra.send({ type: 'hello', id: `again-${i}`, token });
      await receivedWithin(extra, (m) => m.re === `again-${i}`);
      if (i > 0) await new Promise((r) => setTimeout(r, 100));
    }
    expect(extra.received.filter((m) => m.type === 'welcome')).toHaveLength(1);
  });

  it('cuts off HTTP headers and bodies that trickle in (408) at their deadlines; a WebSocket outlives them', async () => {
    const url = await start({ BAIZE_HTTP_HEADERS_TIMEOUT_S: '1', BAIZE_HTTP_REQUEST_TIMEOUT_S: '2' });
    const port = Number(new URL(server!.url).port);
    const ws = await open(url);
    ws.send({ type: 'hello' });
    const [headers, body, idle] = await Promise.all([
      trickle(port, 'GET / HTTP/1.1\r\nHost: x\r\n', 'X-Slow: 1\r\n', 200, 10_000),
      trickle(port, 'POST /api/practice HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 1000\r\n\r\n{', ' ', 200, 10_000),
      trickle(port, '', '', 1000, 10_000),
    ]);
    for (const slow of [headers, body, idle]) {
      expect(slow).not.toBe('open');
      if (slow === 'open') continue;
      expect(slow.answer).toMatch(/^HTTP\/1\.1 408 /);
    }
    expect(await endedWithin(ws, 0)).toBe('open');
    // The body reader gave up quietly: no internal error in the log.
    expect(server!.stderr()).toBe('');
  }, 30_000);
});
