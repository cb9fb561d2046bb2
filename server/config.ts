// The server's configuration, read from the environment once at start.
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';
import { PRACTICE_LIMITS } from './api/rate-limit.ts';
import { RATED_MIN_PLAY_MS } from './ratings/policy.ts';
import { MAX_TABS_PER_PLAYER } from '../shared/protocol/index.ts';
import { availableParallelism } from 'node:os';

/** The least pause before the computer's move that a person can follow (ms). */
export const COMPUTER_PAUSE_MS = 800;
/** The computer's think budget per move (ms). */
export const COMPUTER_THINK_MS = 10_000;

export const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));

export interface Config {
  readonly host: string;
  readonly port: number;
  readonly dbPath: string;
  /** PostgreSQL instead of the SQLite file (BAIZE_DATABASE_URL, postgres://...); undefined: SQLite. */
  readonly databaseUrl: string | undefined;
  /** Several processes over Redis (BAIZE_REDIS_URL, redis://...); needs databaseUrl. Undefined: one process. */
  readonly redisUrl: string | undefined;
  /** This process's name in the cluster (BAIZE_PROCESS_ID); undefined: made up at start. */
  readonly processId: string | undefined;
  readonly migrationsDir: string;
  readonly clientDir: string;
  /** How long a dropped player's seat is held (ms). */
  readonly seatHoldMs: number;
  /** Interval between pings of each socket (ms). */
  readonly pingMs: number;
  /** New players (guests) one address may make an hour. */
  readonly guestsPerAddress: number;
  /** How long a player who never played is kept after they were last seen (ms). */
  readonly guestKeepMs: number;
  /** Practice requests (start and submit) a player may make a minute. */
  readonly practicePerMinute: number;
  /** Practice requests one address (an IPv6 /64) may make a minute. */
  readonly practicePerAddressPerMinute: number;
  /** Server time from a match's start to its result below which it is not rated (ms; 0: no minimum). */
  readonly ratedMinPlayMs: number;
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
  /** Worker threads where the computer thinks (BAIZE_COMPUTER_WORKERS; default min(2, cores)). */
  readonly computerWorkers: number;
  /** The least pause before the computer's move, once the balls have stopped (ms; BAIZE_COMPUTER_PAUSE_MS). */
  readonly computerPauseMs: number;
  /** Longest the computer may think about one move before it plays a simple stroke (ms; BAIZE_COMPUTER_THINK_MS). */
  readonly computerThinkMs: number;
  /** Serve GET /diagnostics/event-loop (the event loop's delay), for load tests (BAIZE_EVENT_LOOP_STATS=1). */
  readonly eventLoopStats: boolean;
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

/** A whole number from 1 to `max`. */
function count(env: NodeJS.ProcessEnv, name: string, fallback: number, max: number, unit: string): number {
  const text = env[name];
  if (text === undefined) return fallback;
  const value = Number(text);
  if (!/^\d+$/.test(text.trim()) || value < 1 || value > max) {
    throw new RangeError(`${name} must be a whole number of ${unit} from 1 to ${max}, got "${text}"`);
  }
  return value;
}

/** Like `seconds`, but 0 is allowed (no minimum). */
function secondsOrZero(env: NodeJS.ProcessEnv, name: string, fallback: number): number {
  const text = env[name];
  if (text === undefined) return fallback * 1000;
  const value = Number(text);
  if (text.trim() === '' || !Number.isFinite(value) || value < 0 || value > 86_400) {
    throw new RangeError(`${name} must be a number of seconds from 0 to 86400, got "${text}"`);
  }
  return value * 1000;
}

export function readConfig(env: NodeJS.ProcessEnv = process.env): Config {
  const portText = env.PORT ?? '8080';
  const port = Number(portText);
  if (!/^\d+$/.test(portText) || !Number.isInteger(port) || port < 0 || port > 65535) {
    throw new RangeError(`PORT must be an integer from 0 to 65535, got "${portText}"`);
  }
  const host = env.HOST ?? '127.0.0.1';
  if (host.trim() === '') throw new RangeError('HOST must not be empty');
  const database = databaseUrl(env);
  const redis = redisUrl(env);
  if (redis !== undefined && database === undefined) {
    throw new RangeError('BAIZE_REDIS_URL needs BAIZE_DATABASE_URL: several processes share one PostgreSQL database, never a SQLite file');
  }
  return {
    host,
    port,
    dbPath: resolve(env.BAIZE_DB ?? resolve(ROOT, 'data/baize.db')),
    databaseUrl: database,
    redisUrl: redis,
    processId: processId(env),
    migrationsDir: resolve(env.BAIZE_MIGRATIONS ?? resolve(ROOT, 'migrations')),
    clientDir: resolve(env.BAIZE_CLIENT_DIR ?? resolve(ROOT, 'dist/client')),
    seatHoldMs: seconds(env, 'BAIZE_SEAT_HOLD_S', 60),
    pingMs: seconds(env, 'BAIZE_PING_S', 15),
    guestsPerAddress: count(env, 'BAIZE_GUESTS_PER_ADDRESS', 20, 1_000_000_000, 'new players an hour'),
    guestKeepMs: count(env, 'BAIZE_GUEST_KEEP_DAYS', 30, 36_500, 'days') * 86_400_000,
    practicePerMinute: count(env, 'BAIZE_PRACTICE_PER_MINUTE', PRACTICE_LIMITS.perPlayer, 1_000_000, 'requests a minute'),
    practicePerAddressPerMinute: count(env, 'BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE', PRACTICE_LIMITS.perAddress, 1_000_000, 'requests a minute'),
    ratedMinPlayMs: secondsOrZero(env, 'BAIZE_RATED_MIN_PLAY_S', RATED_MIN_PLAY_MS / 1000),
    ...limits(env),
    computerWorkers: count(env, 'BAIZE_COMPUTER_WORKERS', Math.min(2, availableParallelism()), 256, 'worker threads'),
    computerPauseMs: milliseconds(env, 'BAIZE_COMPUTER_PAUSE_MS', COMPUTER_PAUSE_MS, 0),
    computerThinkMs: milliseconds(env, 'BAIZE_COMPUTER_THINK_MS', COMPUTER_THINK_MS, 1),
    eventLoopStats: env.BAIZE_EVENT_LOOP_STATS === '1',
  };
}

/** BAIZE_DATABASE_URL: a postgres:// (or postgresql://) URL; unset or empty means the SQLite file. */
function databaseUrl(env: NodeJS.ProcessEnv): string | undefined {
  return serviceUrl(env, 'BAIZE_DATABASE_URL', ['postgres:', 'postgresql:'], 'postgres://user:password@host:5432/baize');
}

/** BAIZE_REDIS_URL: a redis:// (or rediss://) URL; unset or empty means one process. */
function redisUrl(env: NodeJS.ProcessEnv): string | undefined {
  return serviceUrl(env, 'BAIZE_REDIS_URL', ['redis:', 'rediss:'], 'redis://host:6379');
}

/**
 * A URL naming a host with one of two schemes, or undefined when unset or empty. The error never
 * repeats the value, which may hold a password.
 */
function serviceUrl(env: NodeJS.ProcessEnv, name: string, schemes: readonly [string, string], example: string): string | undefined {
  const text = env[name]?.trim();
  if (text === undefined || text === '') return undefined;
  let url: URL;
  try {
    url = new URL(text);
  } catch {
    throw new RangeError(`${name} must be a URL such as ${example} (this one does not parse)`);
  }
  if (!schemes.includes(url.protocol)) throw new RangeError(`${name} must start with ${schemes[0]}// or ${schemes[1]}//, got ${url.protocol}//`);
  if (url.hostname === '') throw new RangeError(`${name} must name a host, as in ${example}`);
  return text;
}

/** BAIZE_PROCESS_ID: letters, digits, '-', '_' and '.', at most 64. */
function processId(env: NodeJS.ProcessEnv): string | undefined {
  const text = env.BAIZE_PROCESS_ID?.trim();
  if (text === undefined || text === '') return undefined;
  if (!/^[A-Za-z0-9._-]{1,64}$/.test(text)) throw new RangeError(`BAIZE_PROCESS_ID must be 1 to 64 letters, digits, '.', '_' or '-', got "${text}"`);
  return text;
}

/** Whole milliseconds from `min` to a minute. */
function milliseconds(env: NodeJS.ProcessEnv, name: string, fallback: number, min: number): number {
  const text = env[name];
  if (text === undefined) return fallback;
  const value = Number(text);
  if (!/^\d+$/.test(text.trim()) || value < min || value > 60_000) throw new RangeError(`${name} must be a whole number of milliseconds from ${min} to 60000, got "${text}"`);
  return value;
}

/** Limits on connections and requests, against clients that hold resources without using them. */
function limits(env: NodeJS.ProcessEnv): Pick<Config, 'helloMs' | 'maxSocketsPerAddress' | 'maxTabsPerPlayer' | 'maxBufferedBytes' | 'headersTimeoutMs' | 'requestTimeoutMs'> {
  const headersTimeoutMs = seconds(env, 'BAIZE_HTTP_HEADERS_TIMEOUT_S', 10);
  const requestTimeoutMs = seconds(env, 'BAIZE_HTTP_REQUEST_TIMEOUT_S', 30);
  if (headersTimeoutMs > requestTimeoutMs) throw new RangeError('BAIZE_HTTP_HEADERS_TIMEOUT_S must not be longer than BAIZE_HTTP_REQUEST_TIMEOUT_S');
  return {
    helloMs: seconds(env, 'BAIZE_HELLO_TIMEOUT_S', 10),
    maxSocketsPerAddress: count(env, 'BAIZE_MAX_SOCKETS_PER_ADDRESS', 50, 1_000_000_000, 'sockets'),
    maxTabsPerPlayer: count(env, 'BAIZE_MAX_TABS_PER_PLAYER', MAX_TABS_PER_PLAYER, 1_000_000, 'sockets'),
    maxBufferedBytes: count(env, 'BAIZE_MAX_BUFFERED_KIB', 1024, 1_000_000_000, 'KiB') * 1024,
    headersTimeoutMs,
    requestTimeoutMs,
  };
}
