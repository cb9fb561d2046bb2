// /healthz says 503 when the database cannot be written, and ok again once it can: a write lock
// held by another connection (anywhere), and, where this user may mount a small tmpfs (root, as in
// CI), a full disk.
import Database from 'better-sqlite3';
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

const running: ServerProcess[] = [];
const mounts: string[] = [];
afterEach(async () => {
  await Promise.all(running.splice(0).map((s) => s.stop('SIGKILL')));
  for (const dir of mounts.splice(0)) execFileSync('umount', ['-l', dir]);
});

async function health(url: string): Promise<{ status: number; body: { ok: boolean; error?: string } }> {
  const res = await fetch(`${url}/healthz`);
  return { status: res.status, body: (await res.json()) as { ok: boolean; error?: string } };
}

/** Waits out the health check's one second of trust in its last good write. */
const pause = (ms = 1100) => new Promise((r) => setTimeout(r, ms));

function canMount(): boolean {
  const dir = tempDir('baize-mount-probe-');
  try {
    execFileSync('mount', ['-t', 'tmpfs', '-o', 'size=64k', 'tmpfs', dir], { stdio: 'ignore' });
    execFileSync('umount', [dir]);
    return true;
  } catch {
    return false;
  }
}

describe('/healthz and a database that cannot be written', () => {
  it('answers 503 while another connection holds the write lock, and 200 once it lets go', async () => {
    const dbPath = join(tempDir(), 'baize.db');
    const server = await startServerProcess({ BAIZE_DB: dbPath });
    running.push(server);
    expect(await health(server.url)).toEqual({ status: 200, body: expect.objectContaining({ ok: true }) });
    const other = new Database(dbPath);
    other.exec('BEGIN EXCLUSIVE');
    await pause();
    const locked = await health(server.url);
    expect(locked.status).toBe(503);
    expect(locked.body.ok).toBe(false);
    expect(locked.body.error).toMatch(/^the database cannot be written: .*locked/);
    other.exec('ROLLBACK');
    other.close();
    expect((await health(server.url)).status).toBe(200);
  });

  it('answers 503 on a full disk, 200 once there is room again', async (ctx) => {
    if (!canMount()) {
      console.warn('skipped: mounting a small tmpfs needs root (CI runs as root)');
      ctx.skip();
    }
    const dir = tempDir('baize-small-disk-');
    execFileSync('mount', ['-t', 'tmpfs', '-o', 'size=4m', 'tmpfs', dir]);
    mounts.push(dir);
    mkdirSync(join(dir, 'db'));
    const server = await startServerProcess({ BAIZE_DB: join(dir, 'db', 'baize.db') });
    running.push(server);
    expect((await health(server.url)).status).toBe(200);

    // Fill every free block.
    const filler = join(dir, 'filler');
    try {
      execFileSync('dd', ['if=/dev/zero', `of=${filler}`, 'bs=4k'], { stdio: 'ignore' });
    } catch {
      // dd stops with "no space left on device": that is the point.
    }
    await pause();
    const full = await health(server.url);
    expect(full.status).toBe(503);
    expect(full.body.error).toMatch(/^the database cannot be written: /);
    rmSync(filler);
    expect((await health(server.url)).status).toBe(200);
  });
});
