// Bare WebSocket and TCP clients for tests of the server's limits: what a hostile or broken client
// does (never say hello, never read, trickle a request in), and how the server ended it.
import { connect as tcpConnect, type Socket } from 'node:net';
import { WebSocket } from 'ws';

export interface Ended {
  readonly code: number;
  readonly reason: string;
}

export interface RawSocket {
  readonly ws: WebSocket;
  /** Every text frame received, parsed. */
  readonly received: { type: string; re?: unknown; code?: string; message?: string }[];
  /** Resolves when the socket closes, with the code and reason the server gave. */
  readonly ended: Promise<Ended>;
  send(msg: object): void;
}

/** Opens a bare WebSocket and resolves once it is open (it may be closed by the server at once). */
export async function rawSocket(url: string): Promise<RawSocket> {
  const ws = new WebSocket(url);
  const received: RawSocket['received'] = [];
  ws.on('message', (data) => received.push(JSON.parse(String(data)) as RawSocket['received'][number]));
  ws.on('error', () => {});
  const ended = new Promise<Ended>((res) => ws.once('close', (code, reason) => res({ code, reason: reason.toString() })));
  await new Promise<void>((res, rej) => {
    ws.once('open', () => res());
    ws.once('error', rej);
  });
  return { ws, received, ended, send: (msg) => ws.send(JSON.stringify(msg)) };
}

/** Tries to open a WebSocket that the server should refuse: the HTTP answer to the upgrade, or 'open'. */
export function refusedUpgrade(url: string): Promise<{ status: number; retryAfter: string | undefined; body: string } | 'open'> {
  return new Promise((res, rej) => {
    const ws = new WebSocket(url);
    ws.once('open', () => {
      ws.terminate();
      res('open');
    });
    ws.once('unexpected-response', (_req, response) => {
      let body = '';
      response.setEncoding('utf8').on('data', (d: string) => (body += d));
      response.on('end', () => res({ status: response.statusCode ?? 0, retryAfter: response.headers['retry-after'], body }));
      response.on('error', rej);
    });
    ws.on('error', () => {});
  });
}

/** The close of a socket, or 'open' if it is still open after `ms`. */
export function endedWithin(s: RawSocket, ms: number): Promise<Ended | 'open'> {
  return Promise.race([s.ended, new Promise<'open'>((res) => setTimeout(() => res('open'), ms))]);
}

/** Waits until a frame matching `ok` has arrived, or throws after `ms`. */
export async function receivedWithin(s: RawSocket, ok: (m: RawSocket['received'][number]) => boolean, ms = 5000): Promise<RawSocket['received'][number]> {
  const t0 = Date.now();
  for (;;) {
    const found = s.received.find(ok);
    if (found) return found;
    if (Date.now() - t0 > ms) throw new Error(`no matching frame within ${ms} ms: ${JSON.stringify(s.received.slice(-3))}`);
    await new Promise((r) => setTimeout(r, 10));
  }
}

/**
 * A plain TCP connection that writes `first`, then `drip` every `everyMs` for as long as it is
 * open; resolves with what the server answered and how long it kept the connection, or with
 * 'open' if it is still open after `ms`.
 */
export function trickle(port: number, first: string, drip: string, everyMs: number, ms: number): Promise<{ answer: string; heldMs: number } | 'open'> {
  return new Promise((res) => {
    const t0 = Date.now();
    let answer = '';
    const socket: Socket = tcpConnect(port, '127.0.0.1', () => socket.write(first));
    const timer = setInterval(() => {
      if (socket.writable) socket.write(drip);
    }, everyMs);
    const give = setTimeout(() => {
      clearInterval(timer);
      socket.destroy();
      res('open');
    }, ms);
    socket.on('data', (d) => (answer += String(d)));
    socket.on('error', () => {});
    socket.on('close', () => {
      clearInterval(timer);
      clearTimeout(give);
      res({ answer, heldMs: Date.now() - t0 });
    });
  });
}
