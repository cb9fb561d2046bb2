// The server's configuration, read from the environment once at start.
import { fileURLToPath } from 'node:url';
import { resolve } from 'node:path';

export const ROOT = resolve(fileURLToPath(new URL('..', import.meta.url)));

export interface Config {
  readonly host: string;
  readonly port: number;
  readonly dbPath: string;
  readonly migrationsDir: string;
  readonly clientDir: string;
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
  };
}
