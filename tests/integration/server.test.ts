import Database from 'better-sqlite3';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { WebSocket } from 'ws';
import { listMigrations } from '../../server/migrate.ts';
import { ROOT, runServerToExit, startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

const VERSION = (JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')) as { version: string }).version;
const LATEST = listMigrations(join(ROOT, 'migrations')).length;

const running: ServerProcess[] = [];
async function start(env: Record<string, string> = {}): Promise<{ server: ServerProcess; dbPath: string }> {
  const dbPath = env.BAIZE_DB ?? join(tempDir(), 'db', 'baize.db');
  const server = await startServerProcess({ ...env, BAIZE_DB: dbPath });
  running.push(server);
  return { server, dbPath };
}
afterEach(async () => {
  await Promise.all(running.splice(0).map((s) => s.stop('SIGKILL')));
});

describe('the server', () => {
  it('answers /healthz with its version and the schema version', async () => {
    const { server } = await start();
    const res = await fetch(`${server.url}/healthz`);
    expect(res.status).toBe(200);
    expect(res.headers.get('content-type')).toMatch(/application\/json/);
    expect(await res.json()).toEqual({ ok: true, version: VERSION, schema: LATEST });
  });

  it('serves the client page at / and its bundle, and 404 elsewhere', async () => {
    const { server } = await start();
    const page = await fetch(`${server.url}/`);
    expect(page.status).toBe(200);
    expect(page.headers.get('content-type')).toMatch(/text\/html/);
    const html = await page.text();
    expect(html).toContain('<h1>baize</h1>');
    expect(html).toContain('src="/app.js"');
    const bundle = await fetch(`${server.url}/app.js`);
    expect(bundle.status).toBe(200);
    expect(bundle.headers.get('content-type')).toMatch(/javascript/);
    expect((await fetch(`${server.url}/../package.json`)).status).toBe(404);
    const missing = await fetch(`${server.url}/nothing-here`);
    expect(missing.status).toBe(404);
    expect(await missing.json()).toEqual({ error: 'not found' });
    // A browser gets the client, whose router says there is no such page.
    const inBrowser = await fetch(`${server.url}/nothing-here`, { headers: { accept: 'text/html,application/xhtml+xml,*/*;q=0.8' } });
    expect(inBrowser.status).toBe(404);
    expect(await inBrowser.text()).toContain('src="/app.js"');
    expect((await fetch(`${server.url}/healthz`, { method: 'POST' })).status).toBe(405);
  });

  it('logs one listening line, creates the database folder and migrates it once', async () => {
    const first = await start();
    expect(first.server.stdout().match(/^listening on http:\/\/127\.0\.0\.1:\d+$/gm)).toHaveLength(1);
    expect(first.server.stdout()).toContain('applied 001_players.sql');
    expect(await first.server.stop()).toBe(0);
    const db = new Database(first.dbPath, { readonly: true });
    expect(db.pragma('user_version', { simple: true })).toBe(LATEST);
    expect(db.pragma('journal_mode', { simple: true })).toBe('wal');
    db.close();

    const second = await start({ BAIZE_DB: first.dbPath });
    expect(second.server.stdout()).toContain(`schema ${LATEST}, up to date`);
    expect(second.server.stdout()).not.toContain('applied');
  });

  it('does not start when a migration fails, and names the file and the reason', async () => {
    const dir = tempDir('baize-migrations-');
    for (const m of listMigrations(join(ROOT, 'migrations'))) writeFileSync(join(dir, m.file), readFileSync(m.path));
    const broken = `${String(LATEST + 1).padStart(3, '0')}_broken.sql`;
    writeFileSync(join(dir, broken), 'CREATE TABLE t (id INTEGER);\nINSERT INTO missing_table VALUES (1);\n');
    const dbPath = join(tempDir(), 'baize.db');
    const exit = await runServerToExit({ BAIZE_DB: dbPath, BAIZE_MIGRATIONS: dir });
    expect(exit.code).toBe(1);
    expect(exit.stdout).not.toContain('listening');
    expect(exit.stderr.trim()).toMatch(new RegExp(`^baize: migration ${broken} failed: no such table: missing_table$`));
    const db = new Database(dbPath, { readonly: true });
    expect(db.pragma('user_version', { simple: true })).toBe(LATEST);
    db.close();
  });

  it('exits with code 1 and one line when the port is taken', async () => {
    const blocker: Server = createServer();
    await new Promise<void>((res) => blocker.listen(0, '127.0.0.1', res));
    const port = (blocker.address() as { port: number }).port;
    try {
      const exit = await runServerToExit({ PORT: String(port), BAIZE_DB: join(tempDir(), 'baize.db') });
      expect(exit.code).toBe(1);
      expect(exit.stderr.trim().split('\n')).toEqual([`baize: port ${port} on 127.0.0.1 is already in use: stop the other server or set PORT`]);
    } finally {
      blocker.close();
    }
  });

  it('refuses a malformed PORT with a clear message', async () => {
    const exit = await runServerToExit({ PORT: 'eighty', BAIZE_DB: join(tempDir(), 'baize.db') });
    expect(exit.code).toBe(1);
    expect(exit.stderr).toContain('PORT must be an integer from 0 to 65535, got "eighty"');
  });

  for (const signal of ['SIGTERM', 'SIGINT'] as const) {
    it(`stops cleanly on ${signal}: open connections closed, database closed, exit code 0`, async () => {
      const { server, dbPath } = await start();
      const socket = new WebSocket(`${server.url.replace('http', 'ws')}/ws`);
      const welcome = await new Promise<string>((res, rej) => {
        socket.once('open', () => socket.send(JSON.stringify({ type: 'hello', name: 'Stopper' })));
        socket.once('message', (data) => res(String(data)));
        socket.once('error', rej);
      });
      expect(JSON.parse(welcome)).toMatchObject({ type: 'welcome', player: { name: 'Stopper' } });
      const closed = new Promise<number>((res) => socket.once('close', (code) => res(code)));
      expect(existsSync(`${dbPath}-wal`)).toBe(true);

      expect(await server.stop(signal)).toBe(0);
      expect(await closed).toBe(1001);
      expect(server.stdout()).toMatch(new RegExp(`${signal} received, stopping\\nstopped\\n$`));
      // better-sqlite3 checkpoints and removes the WAL file when the last connection closes.
      expect(existsSync(`${dbPath}-wal`)).toBe(false);
      await expect(fetch(`${server.url}/healthz`)).rejects.toThrow();
    });
  }
});
