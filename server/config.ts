// The server's configuration, read from the environment once at start.
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import { MAX_TABS_PER_PLAYER } from '../shared/protocol/index.ts';

export const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));

export interface Config {
  readonly host: string;
  readonly port: number;
  readonly dbPath: string;
  readonly migrationsDir: string;
  readonly clientDir: string;
  /** How long a dropped player's seat is held (ms). */
  readonly seatHoldMs: number;
  /** Interval between pings of each socket (ms). */
  readonly pingMs: number;
  /** How long a new socket has to say hello before it is closed (ms). */
  readonly helloMs: number;
  /** WebSocket connections open at once from one address (an IPv6 /64 counts as one). */
  readonly maxSocketsPerAddress: number;
  /** Sockets one player may have welcomed at once (tabs). */
  readonly maxTabsPerPlayer: number;
  /** Bytes the server may hold unsent for one socket before it drops it (a client that does not read). */
  readonly maxBufferedBytes: number;
  /** HTTP: how long a request's headers, and the whole request with its body, may take to arrive (ms). */
  readonly headersTimeoutMs: number;
  readonly requestTimeoutMs: number;
}

function seconds(env: NodeJS.ProcessEnv, name: string, fallback: number): number {
  const text = env[name];
  if (text === undefined) return fallback * 1000;
  const value = Number(text);
  if (text.trim() === '' || !Number.isFinite(value) || value <= 0 || value > 86_400) {
    throw new RangeError(`${name} must be a number of seconds above 0 and at most 86400, got "${text}"`);
  }
  return value * 1000;
}

function count(env: NodeJS.ProcessEnv, name: string, fallback: number): number {
  const text = env[name];
  if (text === undefined) return fallback;
  const value = Number(text);
  if (!/^\d+$/.test(text.trim()) || !Number.isSafeInteger(value) || value < 1) {
    throw new RangeError(`${name} must be a whole number of at least 1, got "${text}"`);
  }
  return value;
}

export function readConfig(env: NodeJS.ProcessEnv = process.env): Config {
  const portText = env.PORT ?? '8080';
  const port = Number(portText);
  if (!/^\d+$/.test(portText) || !Number.isInteger(port) || port < 0 || port > 65535) {
    throw new RangeError(`PORT must be an integer from 0 to 65535, got "${portText}"`);
  }
  const host = env.HOST ?? '127.0.0.1';
  if (host.trim() === '') throw new RangeError('HOST must not be empty');
  return {
    host,
    port,
    dbPath: resolve(env.BAIZE_DB ?? resolve(ROOT, 'data/baize.db')),
    migrationsDir: resolve(env.BAIZE_MIGRATIONS ?? resolve(ROOT, 'migrations')),
    clientDir: resolve(env.BAIZE_CLIENT_DIR ?? resolve(ROOT, 'dist/client')),
    seatHoldMs: seconds(env, 'BAIZE_SEAT_HOLD_S', 60),
    pingMs: seconds(env, 'BAIZE_PING_S', 15),
    ...limits(env),
  };
}

/** Limits on connections and requests, against clients that hold resources without using them. */
function limits(env: NodeJS.ProcessEnv): Pick<Config, 'helloMs' | 'maxSocketsPerAddress' | 'maxTabsPerPlayer' | 'maxBufferedBytes' | 'headersTimeoutMs' | 'requestTimeoutMs'> {
  const headersTimeoutMs = seconds(env, 'BAIZE_HTTP_HEADERS_TIMEOUT_S', 10);
  const requestTimeoutMs = seconds(env, 'BAIZE_HTTP_REQUEST_TIMEOUT_S', 30);
  if (headersTimeoutMs > requestTimeoutMs) throw new RangeError('BAIZE_HTTP_HEADERS_TIMEOUT_S must not be longer than BAIZE_HTTP_REQUEST_TIMEOUT_S');
  return {
    helloMs: seconds(env, 'BAIZE_HELLO_TIMEOUT_S', 10),
    maxSocketsPerAddress: count(env, 'BAIZE_MAX_SOCKETS_PER_ADDRESS', 50),
    maxTabsPerPlayer: count(env, 'BAIZE_MAX_TABS_PER_PLAYER', MAX_TABS_PER_PLAYER),
    maxBufferedBytes: count(env, 'BAIZE_MAX_BUFFERED_KIB', 1024) * 1024,
    headersTimeoutMs,
    requestTimeoutMs,
  };
}
