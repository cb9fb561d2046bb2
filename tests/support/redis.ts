// A real redis-server for the tests, started in a temporary folder on a free 127.0.0.1 port with
// persistence off, and stopped after; never a shared or system one. Without redis-server the tests
// skip with a message, unless BAIZE_REQUIRE_REDIS=1 (CI) makes them mandatory.
import { execFileSync, spawn, type ChildProcess } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { freePort } from './free-port.ts';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createClient } from '@redis/client';

export const REQUIRE_REDIS = process.env.BAIZE_REQUIRE_REDIS === '1';

function hasRedis(): boolean {
  try {
    execFileSync('redis-server', ['--version'], { stdio: 'pipe' });
    return true;
  } catch {
    return false;
  }
}

/** True when the tests should run; logs why they skip otherwise. */
export function redisAvailable(): boolean {
  if (hasRedis()) return true;
  if (REQUIRE_REDIS) return true; // run and fail loudly: CI promised Redis
  console.warn('Redis tests skipped: no redis-server found (apt-get install redis-server; BAIZE_REQUIRE_REDIS=1 makes this a failure)');
  return false;
}

export interface RedisServer {
  /** redis://127.0.0.1:port */
  readonly url: string;
  /** SIGKILL, as a crash would (stop() still cleans up). */
  kill(): void;
  stop(): Promise<void>;
}

export async function startRedis(): Promise<RedisServer> {
  if (!hasRedis()) throw new Error("BAIZE_REQUIRE_REDIS=1 but no redis-server: install Debian's redis-server package");
  const dir = mkdtempSync(join(tmpdir(), 'baize-redis-'));
  const port = await freePort();
  const server: ChildProcess = spawn('redis-server', ['--bind', '127.0.0.1', '--port', String(port), '--save', '', '--appendonly', 'no', '--dir', dir], {
    cwd: dir,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let log = '';
  server.stdout!.on('data', (d: Buffer) => (log += d.toString()));
  server.stderr!.on('data', (d: Buffer) => (log += d.toString()));
  const url = `redis://127.0.0.1:${port}`;
  const deadline = Date.now() + 10_000;
  for (;;) {
    const c = createClient({ url, socket: { reconnectStrategy: false } });
    c.on('error', () => undefined);
    try {
      await c.connect();
      await c.ping();
      await c.quit();
      break;
    } catch (err) {
      if (server.exitCode !== null || Date.now() > deadline) {
        server.kill('SIGKILL');
        throw new Error(`redis-server did not start: ${(err as Error).message}\n${log}`);
      }
      await new Promise((r) => setTimeout(r, 50));
    }
  }
  return {
    url,
    kill: () => server.kill('SIGKILL'),
    async stop() {
      if (server.exitCode === null && server.signalCode === null) {
        await new Promise<void>((resolve) => {
          const t = setTimeout(() => server.kill('SIGKILL'), 3000);
          server.once('exit', () => {
            clearTimeout(t);
            resolve();
          });
          server.kill('SIGTERM');
        });
      }
      rmSync(dir, { recursive: true, force: true });
    },
  };
}
