// The thin WebSocket binding: frames in, parsed and rate-limited, handed to the game service; the
// service's deliveries out to sockets. Liveness by ping: a socket that misses two pongs is dropped.
import type { WebSocket, WebSocketServer } from 'ws';
import { CLOSE_POLICY, parseClientMessage, RATE_BURST, RATE_PER_SECOND } from '../../shared/protocol/index.ts';
import type { ConnId, Delivery, GameService } from '../game/service.ts';
import { TokenBucket } from './token-bucket.ts';

export interface BindingOptions {
  /** Interval between pings (ms); a socket that has not answered the last two is dropped. */
  readonly pingMs: number;
  /** Interval of the service's timers: shot clocks and seat holds (ms). */
  readonly tickMs: number;
}

interface Conn {
  readonly socket: WebSocket;
  readonly bucket: TokenBucket;
  missedPings: number;
}

export function bindWebSocket(wss: WebSocketServer, service: GameService, options: BindingOptions): { stop(): void } {
  const conns = new Map<ConnId, Conn>();
  let nextId = 1;

  // The service answers every command itself; this guard only keeps a bug from taking the process down.
  const safely = (what: string, run: () => readonly Delivery[]): void => {
    try {
      deliver(run());
    } catch (err) {
      console.error(`${what}: ${(err as Error).stack ?? String(err)}`);
    }
  };

  const deliver = (deliveries: readonly Delivery[]): void => {
    for (const d of deliveries) {
      const text = JSON.stringify(d.message);
      for (const id of d.to) {
        const c = conns.get(id);
        if (c && c.socket.readyState === c.socket.OPEN) c.socket.send(text);
      }
    }
  };

  wss.on('connection', (socket, req) => {
    const id = nextId++;
    service.open(id, req.socket.remoteAddress ?? '');
    const conn: Conn = { socket, bucket: new TokenBucket(RATE_PER_SECOND, RATE_BURST, Date.now()), missedPings: 0 };
    conns.set(id, conn);
    socket.on('pong', () => {
      conn.missedPings = 0;
    });
    socket.on('message', (data, isBinary) => {
      if (!conn.bucket.take(Date.now())) {
        socket.close(CLOSE_POLICY, 'too many messages');
        return;
      }
      if (isBinary) {
        safely('reject', () => service.reject(id, 'bad-message', 'frames must be JSON text'));
        return;
      }
      const parsed = parseClientMessage(data.toString());
      safely('handle', () => (parsed.ok ? service.handle(id, parsed.message) : service.reject(id, parsed.code, parsed.message, parsed.re)));
    });
    socket.on('close', () => {
      conns.delete(id);
      safely('close', () => service.close(id));
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
  const ticker = setInterval(() => safely('tick', () => service.tick()), options.tickMs);
  pinger.unref();
  ticker.unref();
  return {
    stop() {
      clearInterval(pinger);
      clearInterval(ticker);
    },
  };
}
