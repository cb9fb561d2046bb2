// A real PostgreSQL server for the tests, started in a temporary folder on a free 127.0.0.1 port
// and stopped after; never a shared or system one. PostgreSQL refuses to run as root, so under
// root (CI) the cluster belongs to the unprivileged user `nobody`. Without PostgreSQL's binaries
// the tests skip with a message, unless BAIZE_REQUIRE_POSTGRES=1 (CI) makes them mandatory.
import { execFileSync, spawn, type ChildProcess } from 'node:child_process';
import { chmodSync, chownSync, existsSync, mkdtempSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir, userInfo } from 'node:os';
import { join } from 'node:path';
import pg from 'pg';
import { freePort } from './free-port.ts';

export const REQUIRE_POSTGRES = process.env.BAIZE_REQUIRE_POSTGRES === '1';

/** The folder with initdb and postgres: pg_config's, Debian's, or the PATH's. */
function binDir(): string | null {
  try {
    const dir = execFileSync('pg_config', ['--bindir'], { encoding: 'utf8' }).trim();
    if (existsSync(join(dir, 'initdb'))) return dir;
  } catch {
    // no pg_config
  }
  const debian = '/usr/lib/postgresql';
  if (existsSync(debian)) {
    for (const v of readdirSync(debian).sort().reverse()) if (existsSync(join(debian, v, 'bin', 'initdb'))) return join(debian, v, 'bin');
  }
  for (const dir of (process.env.PATH ?? '').split(':')) if (dir && existsSync(join(dir, 'initdb')) && existsSync(join(dir, 'postgres'))) return dir;
  return null;
}

/** True when the tests should run; logs why they skip otherwise. */
export function postgresAvailable(): boolean {
  if (binDir() !== null) return true;
  if (REQUIRE_POSTGRES) return true; // run and fail loudly: CI promised PostgreSQL
  console.warn("PostgreSQL tests skipped: no initdb found (apt-get install postgresql; BAIZE_REQUIRE_POSTGRES=1 makes this a failure)");
  return false;
}

export interface PostgresServer {
  /** postgres://... of a database made for the caller. */
  readonly url: string;
  /** Another empty database on the same server. */
  database(name: string): Promise<string>;
  stop(): Promise<void>;
}

export interface PostgresStartOptions {
  /** Flush commits to disk as a production server does (benchmarks); tests skip it for speed. */
  readonly durable?: boolean;
}

/** Starts a fresh cluster; the caller stops it (afterAll). */
export async function startPostgres(options: PostgresStartOptions = {}): Promise<PostgresServer> {
  const bin = binDir();
  if (bin === null) throw new Error('BAIZE_REQUIRE_POSTGRES=1 but no PostgreSQL: install Debian\'s postgresql package');
  const root = userInfo().uid === 0;
  // `nobody` owns the cluster under root: its uid and gid from the system.
  const as = root ? { uid: Number(execFileSync('id', ['-u', 'nobody'], { encoding: 'utf8' })), gid: Number(execFileSync('id', ['-g', 'nobody'], { encoding: 'utf8' })) } : {};
  const dir = mkdtempSync(join(tmpdir(), 'baize-pg-'));
  chmodSync(dir, 0o755);
  const data = join(dir, 'data');
  if (root) chownSync(dir, as.uid!, as.gid!);
  const env = { ...process.env, LC_ALL: 'C' };
  execFileSync(join(bin, 'initdb'), ['-D', data, '-U', 'baize', '-A', 'trust', '-E', 'UTF8', '--no-sync'], { ...as, env, cwd: dir, stdio: 'pipe' });
  const port = await freePort();
  const server: ChildProcess = spawn(
    join(bin, 'postgres'),
    ['-D', data, '-p', String(port), '-k', dir, '-c', 'listen_addresses=127.0.0.1', ...(options.durable ? [] : ['-c', 'fsync=off', '-c', 'full_page_writes=off'])],
    { ...as, env, cwd: dir, stdio: ['ignore', 'ignore', 'pipe'] },
  );
  let log = '';
  server.stderr!.on('data', (d: Buffer) => (log += d.toString()));
  const base = `postgres://baize@127.0.0.1:${port}`;
  const deadline = Date.now() + 20_000;
  for (;;) {
    const c = new pg.Client({ connectionString: `${base}/postgres` });
    try {
      await c.connect();
      await c.end();
      break;
    } catch (err) {
      await c.end().catch(() => undefined);
      if (server.exitCode !== null || Date.now() > deadline) {
        server.kill('SIGKILL');
        throw new Error(`PostgreSQL did not start: ${(err as Error).message}\n${log}`);
      }
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  const database = async (name: string): Promise<string> => {
    const c = new pg.Client({ connectionString: `${base}/postgres` });
    await c.connect();
    try {
      await c.query(`CREATE DATABASE ${pg.escapeIdentifier(name)}`);
    } finally {
      await c.end();
    }
    return `${base}/${name}`;
  };
  const url = await database('baize');
  return {
    url,
    database,
    async stop() {
      // Fast shutdown (SIGINT); killed if it lingers.
      await new Promise<void>((resolve) => {
        const t = setTimeout(() => server.kill('SIGKILL'), 5000);
        server.once('exit', () => {
          clearTimeout(t);
          resolve();
        });
        server.kill('SIGINT');
      });
      rmSync(dir, { recursive: true, force: true });
    },
  };
}
