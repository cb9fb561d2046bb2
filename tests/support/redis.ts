// A real redis-server for the tests, started in a temporary folder on a free 127.0.0.1 port and
// stopped after; never a shared or system one. Without the binary the tests skip with a message,
// unless BAIZE_REQUIRE_REDIS=1 (CI) makes them mandatory.
import { execFileSync, spawn, type ChildProcess } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { createConnection } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { freePort } from './free-port.ts';

export const REQUIRE_REDIS = process.env.BAIZE_REQUIRE_REDIS === '1';

function binary(): string | null {
  try {
    return execFileSync('sh', ['-c', 'command -v redis-server'], { encoding: 'utf8' }).trim() || null;
  } catch {
    return null;
  }
}

/** True when the tests should run; logs why they skip otherwise. */
export function redisAvailable(): boolean {
  if (binary() !== null) return true;
  if (REQUIRE_REDIS) return true; // run and fail loudly: CI promised Redis
  console.warn('Redis tests skipped: no redis-server found (apt-get install redis-server; BAIZE_REQUIRE_REDIS=1 makes this a failure)');
  return false;
}

function answers(port: number): Promise<boolean> {
  return new Promise((resolve) => {
    const c = createConnection({ host: '127.0.0.1', port });
    c.once('connect', () => c.write('PING\r\n'));
    c.once('data', (d) => { c.destroy(); resolve(d.toString().startsWith('+PONG')); });
    c.once('error', () => resolve(false));
  });
}

export interface RedisServer {
  readonly url: string;
  readonly port: number;
  /** kill -9, for tests of a lost server; start() brings it back on the same port. */
  kill(): Promise<void>;
  start(): Promise<void>;
  stop(): Promise<void>;
}

/** Starts a fresh redis-server; the caller stops it (afterAll). */
export async function startRedis(): Promise<RedisServer> {
  const bin = binary();
  if (bin === null) throw new Error("BAIZE_REQUIRE_REDIS=1 but no redis-server: install Debian's redis-server package");
  const dir = mkdtempSync(join(tmpdir(), 'baize-redis-'));
  const port = await freePort();
  let server: ChildProcess | null = null;
  const exited = (p: ChildProcess) => new Promise<void>((r) => (p.exitCode !== null || p.signalCode !== null ? r() : p.once('exit', () => r())));
  const start = async () => {
    const p = spawn(bin, ['--bind', '127.0.0.1', '--port', String(port), '--save', '', '--appendonly', 'no', '--dir', dir], { cwd: dir, stdio: ['ignore', 'pipe', 'pipe'] });
    let log = '';
    p.stdout!.on('data', (d: Buffer) => (log += d.toString()));
    p.stderr!.on('data', (d: Buffer) => (log += d.toString()));
    server = p;
    const deadline = Date.now() + 10_000;
    while (!(await answers(port))) {
      if (p.exitCode !== null || Date.now() > deadline) {
        p.kill('SIGKILL');
        throw new Error(`redis-server did not start:\n${log}`);
      }
      await new Promise((r) => setTimeout(r, 50));
    }
  };
  await start();
  return {
    url: `redis://127.0.0.1:${port}`,
    port,
    async kill() {
      if (!server) return;
      const p = server;
      server = null;
      p.kill('SIGKILL');
      await exited(p);
    },
    start,
    async stop() {
      if (server) {
        const p = server;
        server = null;
        const t = setTimeout(() => p.kill('SIGKILL'), 5000);
        p.kill('SIGTERM');
        await exited(p);
        clearTimeout(t);
      }
      rmSync(dir, { recursive: true, force: true });
    },
  };
}
