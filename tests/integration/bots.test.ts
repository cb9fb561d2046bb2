// The headless bots against the real server: two rooms of bots, each in its own process, play for
// a few seconds and sum it up in one JSON line, with shots played and no error.
import { spawn } from 'node:child_process';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import type { Summary } from '../../bots/summary.ts';
import { ROOT, startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

function runBots(args: string[]): Promise<{ code: number | null; stdout: string; stderr: string }> {
  const child = spawn(process.execPath, ['--import', 'tsx', 'bots/main.ts', ...args], { cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  child.stdout.setEncoding('utf8').on('data', (d: string) => (stdout += d));
  child.stderr.setEncoding('utf8').on('data', (d: string) => (stderr += d));
  return new Promise((res) => child.once('exit', (code) => res({ code, stdout, stderr })));
}

let server: ServerProcess | undefined;
afterEach(async () => {
  await server?.stop('SIGKILL');
  server = undefined;
});

describe('bots/main.ts', () => {
  it('plays two rooms against the real server and prints one summary line with shots and no errors', async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db') });
    const url = `${server.url.replace(/^http/, 'ws')}/ws`;
    const started = Date.now();
    const { code, stdout, stderr } = await runBots(['--url', url, '--rooms', '2', '--seconds', '10', '--kind', 'mixed']);
    expect(code, stderr).toBe(0);
    expect(Date.now() - started).toBeLessThan(25_000);
    const lines = stdout.trim().split('\n');
    expect(lines).toHaveLength(1);
    const summary = JSON.parse(lines[0]!) as Summary;
    expect(summary).toMatchObject({ rooms: 2, sockets: 4, errors: 0, disconnects: 0, setupFailures: 0 });
    expect(summary.shots).toBeGreaterThan(0);
    expect(summary.rttMs.p50).toBeGreaterThan(0);
    expect(summary.rttMs.p99).toBeGreaterThanOrEqual(summary.rttMs.p50!);
    expect(summary.yardstickMs.p50).toBeGreaterThan(0);
    expect(summary.seconds).toBeGreaterThanOrEqual(10);
  }, 40_000);

  it('exits non-zero at once when nothing listens at the URL', async () => {
    const { code, stdout } = await runBots(['--url', 'ws://127.0.0.1:9/ws', '--rooms', '1', '--seconds', '10']);
    expect(code).not.toBe(0);
    expect(stdout).toBe('');
  }, 20_000);
});
