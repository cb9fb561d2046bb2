// The server: database, HTTP and WebSocket on one port, and a clean stop.
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { WebSocketServer } from 'ws';
import type { Config } from './config.ts';
import { healthCheck } from './health.ts';
import { createRequestHandler } from './http-routes.ts';
import { loadStaticFiles } from './static-files.ts';
import { VERSION } from './version.ts';
import { MAX_FRAME_BYTES } from '../shared/protocol/index.ts';
import { GameService } from './game/service.ts';
import { openStore, type AsyncStore } from './store/index.ts';
import { Api } from './api/routes.ts';
import { AddressCap } from './ws/address.ts';
import { bindWebSocket } from './ws/binding.ts';
import { WorkerPool } from './workers/pool.ts';
import { eventLoopStats } from './event-loop-stats.ts';
import { ClusterNode } from './cluster/index.ts';

export interface RunningServer {
  /** http://host:port with the port actually bound (PORT=0 picks a free one). */
  readonly url: string;
  readonly port: number;
  readonly schema: number;
  readonly migrationsApplied: readonly string[];
  /** Stops taking connections, closes the open ones and the database. Idempotent. */
  close(): Promise<void>;
}

export class PortInUseError extends Error {
  override readonly name = 'PortInUseError';
  constructor(host: string, port: number) {
    super(`port ${port} on ${host} is already in use: stop the other server or set PORT`);
  }
}

/** How long the health check waits for a database lock held elsewhere (ms): short, it runs on the event loop. */
const HEALTH_LOCK_WAIT_MS = 100;

/** Largest WebSocket message accepted, in bytes: anything larger closes the connection (1009). */
export const MAX_MESSAGE_BYTES = MAX_FRAME_BYTES;

export async function startServer(config: Config): Promise<RunningServer> {
  // The SQLite file, or PostgreSQL with BAIZE_DATABASE_URL; migrated, and players from before
  // migration 006 given their name keys, as it opens.
  const { store, applied } = await openStore(config);
  let service: GameService;
  let workers: WorkerPool | undefined;
  let schema: number;
  // With BAIZE_REDIS_URL this process is one of several (docs/scale.md).
  let cluster: ClusterNode | undefined;
  try {
    schema = await store.schemaVersion();
    if (config.redisUrl !== undefined) cluster = await ClusterNode.start(config.redisUrl, config.processId === undefined ? {} : { processId: config.processId });
    workers = new WorkerPool({ size: config.computerWorkers, budgetMs: config.computerThinkMs });
    service = await GameService.start(store, {
      seatHoldMs: config.seatHoldMs,
      guestsPerAddress: config.guestsPerAddress,
      guestKeepMs: config.guestKeepMs,
      ratedMinPlayMs: config.ratedMinPlayMs,
      maxTabsPerPlayer: config.maxTabsPerPlayer,
      computer: { thinker: workers, pauseMs: config.computerPauseMs },
      ...(cluster ? { peers: cluster } : {}),
    });
  } catch (err) {
    void workers?.close();
    await cluster?.close();
    await store.close();
    throw err;
  }
  const files = loadStaticFiles(config.clientDir);
  // The HTTP side (health, API) reads through the same store as the game service.
  const reads: AsyncStore = store;
  const health = healthCheck({ version: VERSION, schema: () => reads.schemaVersion(), probeWrite: () => reads.probeWrite(HEALTH_LOCK_WAIT_MS) });
  const api = new Api(reads, { perPlayer: config.practicePerMinute, perAddress: config.practicePerAddressPerMinute }, workers);
  const loop = config.eventLoopStats ? eventLoopStats() : undefined;
  const handler = createRequestHandler(files, health, api, loop);
  // Slow requests hold a socket each: headers and whole requests have deadlines (answered 408),
  // checked every second rather than Node's default 30 s.
  const http = createServer(
    { headersTimeout: config.headersTimeoutMs, requestTimeout: config.requestTimeoutMs, connectionsCheckingInterval: Math.min(1000, config.headersTimeoutMs) },
    handler,
  );
  try {
    await new Promise<void>((resolve, reject) => {
      const onError = (err: NodeJS.ErrnoException) => {
        reject(err.code === 'EADDRINUSE' ? new PortInUseError(config.host, config.port) : err);
      };
      http.once('error', onError);
      http.listen(config.port, config.host, () => {
        http.off('error', onError);
        resolve();
      });
    });
  } catch (err) {
    void workers.close();
    loop?.stop();
    await cluster?.close();
    await store.close();
    throw err;
  }

  // Attached only once listening: a WebSocketServer re-emits its HTTP server's errors.
  const perAddress = new AddressCap(config.maxSocketsPerAddress);
  const wss = new WebSocketServer({ server: http, path: '/ws', maxPayload: MAX_MESSAGE_BYTES, perMessageDeflate: false, verifyClient: perAddress.verify });
  const binding = bindWebSocket(wss, service, {
    pingMs: config.pingMs,
    tickMs: 250,
    helloMs: config.helloMs,
    perAddress,
    maxBufferedBytes: config.maxBufferedBytes,
    ...(cluster ? { nextConnId: () => cluster.nextConnId() } : {}),
  });

  const { port } = http.address() as AddressInfo;
  const hostInUrl = config.host.includes(':') ? `[${config.host}]` : config.host;
  let closing: Promise<void> | undefined;
  return {
    url: `http://${hostInUrl}:${port}`,
    port,
    schema,
    migrationsApplied: applied,
    close() {
      closing ??= new Promise<void>((resolve) => {
        binding.stop();
        loop?.stop();
        void workers.close();
        for (const socket of wss.clients) socket.close(1001, 'server shutting down');
        wss.close();
        http.close(() => {
          // Leases given up first, so that the other processes take the rooms over at once.
          (cluster?.close() ?? Promise.resolve())
            .then(() => store.close())
            .then(resolve, (err: unknown) => {
              console.error(`closing the store: ${(err as Error).stack ?? String(err)}`);
              resolve();
            });
        });
        http.closeIdleConnections();
        // Sockets that do not finish their close handshake promptly are cut.
        setTimeout(() => {
          for (const socket of wss.clients) socket.terminate();
          http.closeAllConnections();
        }, 1000).unref();
      });
      return closing;
    },
  };
}
