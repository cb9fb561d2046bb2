// The thin WebSocket binding: frames in, parsed and rate-limited, handed to the game service; the
// service's deliveries out to sockets. Liveness by ping: a socket that misses two pongs is dropped.
// Limits against sockets that hold resources without using them: so many per address (counted
// here, refused at the upgrade by AddressCap), a deadline for hello, and a cap on what the server
// holds unsent for a socket that does not read.
import type { WebSocket, WebSocketServer } from 'ws';
import { CLOSE_POLICY, parseClientMessage, RATE_BURST, RATE_PER_SECOND } from '../../shared/protocol/index.ts';
import type { ConnId, Delivery, GameService } from '../game/service.ts';
import type { AddressCap } from './address.ts';
import { StallWatch } from './stall-watch.ts';
import { TokenBucket } from '../token-bucket.ts';

export interface BindingOptions {
  /** Interval between pings (ms); a socket that has not answered the last two is dropped. */
  readonly pingMs: number;
  /** Interval of the service's timers: shot clocks and seat holds (ms). */
  readonly tickMs: number;
  /** How long a socket has to say hello (ms) before it is closed with 1008. */
  readonly helloMs: number;
  /** Sockets open at once per address: its verify hook refuses more at the upgrade; counted here. */
  readonly perAddress: AddressCap;
  /** Bytes held unsent for one socket beyond which it is dropped (it may reconnect and resume). */
  readonly maxBufferedBytes: number;
  /** Connection ids unique across processes (undefined: none to hand right now); default: counted here. */
  readonly nextConnId?: () => number | undefined;
}

/** How long a socket closed by the server has to answer the close before it is cut. */
const CLOSE_GRACE_MS = 1000;

interface Conn {
  readonly socket: WebSocket;
  /** The socket's last operation in the service: the next waits for it, so its deliveries go out in order. */
  queue: Promise<void>;
  readonly bucket: TokenBucket;
  missedPings: number;
  welcomed: boolean;
  helloTimer?: NodeJS.Timeout;
}

export function bindWebSocket(wss: WebSocketServer, service: GameService, options: BindingOptions): { stop(): void } {
  const conns = new Map<ConnId, Conn>();
  const stalls = new StallWatch();
  let nextId = 1;

  // The service answers every command itself; this guard only keeps a bug from taking the process down.
  const safely = async (what: string, run: () => Promise<readonly Delivery[]> | readonly Delivery[]): Promise<void> => {
    try {
      deliver(await run());
    } catch (err) {
      console.error(`${what}: ${(err as Error).stack ?? String(err)}`);
    }
  };
  /** A socket's frames are handled one after another: each waits for the one before, and its deliveries go out after that one's. */
  const inOrder = (conn: Conn, what: string, run: () => Promise<readonly Delivery[]> | readonly Delivery[]): void => {
    conn.queue = conn.queue.then(() => safely(what, run));
  };

  const deliver = (deliveries: readonly Delivery[]): void => {
    for (const d of deliveries) {
      // Encoded once for all its sockets: every socket's queue holds the same bytes.
      const bytes = Buffer.from(JSON.stringify(d.message));
      for (const id of d.to) {
        const c = conns.get(id);
        if (!c || c.socket.readyState !== c.socket.OPEN) continue;
        if (d.message.type === 'welcome') c.welcomed = true;
        c.socket.send(bytes, { binary: false });
        // A client that does not read would have the server queue everything for it forever.
        if (c.socket.bufferedAmount > options.maxBufferedBytes) c.socket.terminate();
      }
    }
  };

  /** Closes with a reason, and cuts the socket if the client does not finish the close promptly. */
  const refuse = (socket: WebSocket, reason: string): void => {
    socket.close(CLOSE_POLICY, reason);
    setTimeout(() => socket.terminate(), CLOSE_GRACE_MS).unref();
  };

  // What the service does by itself (the computer's moves) goes out the same way.
  service.attach((deliveries) => deliver(deliveries));

  const helloDeadline = (conn: Conn, ms: number): NodeJS.Timeout =>
    setTimeout(() => {
      if (conn.welcomed) return;
      // A hello queued behind a stall of the server's own is given the time it lost.
      if (stalls.recent(Date.now()) > 0) conn.helloTimer = helloDeadline(conn, CLOSE_GRACE_MS);
      else refuse(conn.socket, `say hello within ${options.helloMs / 1000} s`);
    }, ms);

  wss.on('connection', (socket, req) => {
    const remote = req.socket.remoteAddress ?? '';
    const id = options.nextConnId ? options.nextConnId() : nextId++;
    if (id === undefined) {
      socket.close(1013, 'try again later');
      return;
    }
    const release = options.perAddress.add(remote);
    service.open(id, remote);
    const conn: Conn = { socket, queue: Promise.resolve(), bucket: new TokenBucket(RATE_PER_SECOND, RATE_BURST, Date.now()), missedPings: 0, welcomed: false };
    conn.helloTimer = helloDeadline(conn, options.helloMs);
    conns.set(id, conn);
    socket.on('pong', () => {
      conn.missedPings = 0;
    });
    socket.on('message', (data, isBinary) => {
      if (socket.readyState !== socket.OPEN) return;
      const now = Date.now();
      // Frames that queued while the server itself stalled arrive together: the bucket may hold
      // what it would have earned during the stall beyond its burst, so that they pass.
      if (!conn.bucket.take(now, (stalls.recent(now) / 1000) * RATE_PER_SECOND)) {
        refuse(socket, 'too many messages');
        return;
      }
      if (isBinary) {
        inOrder(conn, 'reject', () => service.reject(id, 'bad-message', 'frames must be JSON text'));
        return;
      }
      const parsed = parseClientMessage(data.toString());
      inOrder(conn, 'handle', () => (parsed.ok ? service.handle(id, parsed.message) : service.reject(id, parsed.code, parsed.message, parsed.re)));
    });
    socket.on('close', () => {
      clearTimeout(conn.helloTimer);
      conns.delete(id);
      release();
      inOrder(conn, 'close', () => service.close(id));
    });
    socket.on('error', () => socket.terminate());
  });

  const pinger = setInterval(() => {
    for (const c of conns.values()) {
      if (c.missedPings >= 2) {
        c.socket.terminate();
        continue;
      }
      c.missedPings++;
      c.socket.ping();
    }
  }, options.pingMs);
  // A tick still running (its rooms waiting on the database) is not joined by another.
  let ticking = false;
  const ticker = setInterval(() => {
    if (ticking) return;
    ticking = true;
    void safely('tick', () => service.tick()).finally(() => (ticking = false));
  }, options.tickMs);
  pinger.unref();
  ticker.unref();
  return {
    stop() {
      clearInterval(pinger);
      clearInterval(ticker);
      stalls.stop();
      for (const c of conns.values()) clearTimeout(c.helloTimer);
    },
  };
}
