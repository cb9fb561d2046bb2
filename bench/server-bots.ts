// Runs one load level: `bots/main.ts` in its own process (so the server's CPU is not shared with the
// bots' in one event loop), and reads its one JSON summary line.
import { spawn } from 'node:child_process';
import { resolve } from 'node:path';
import type { Summary } from '../bots/summary.ts';

const ROOT = resolve(import.meta.dirname, '..');

export interface BotsRun {
  readonly summary: Summary;
  /** performance.now() when the summary line arrived: the end of play. */
  readonly at: number;
}

export interface BotsLoad {
  readonly url: string;
  readonly rooms: number;
  readonly seconds: number;
  readonly thinkMs: number;
  readonly kind: string;
}

/** Spawns the bots and resolves once they exit, with their summary; `onSummary` runs as it arrives. */
export function runBots(load: BotsLoad, onSummary: () => void, signal?: AbortSignal): Promise<BotsRun> {
  const args = ['--import', 'tsx', 'bots/main.ts', '--url', load.url, '--rooms', String(load.rooms), '--seconds', String(load.seconds)];
  args.push('--think-ms', String(load.thinkMs), '--kind', load.kind, '--quick');
  const child = spawn(process.execPath, args, { cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe'], ...(signal ? { signal } : {}) });
  let out = '';
  let err = '';
  let run: BotsRun | undefined;
  child.stdout.setEncoding('utf8').on('data', (d: string) => {
    out += d;
    const complete = out.split('\n').slice(0, -1);
    const line = complete.find((l) => l.startsWith('{'));
    if (line !== undefined && run === undefined) {
      run = { summary: JSON.parse(line) as Summary, at: performance.now() };
      onSummary();
    }
  });
  child.stderr.setEncoding('utf8').on('data', (d: string) => (err += d));
  // The bots stop by themselves; this is only for a run that hangs.
  const kill = setTimeout(() => child.kill('SIGKILL'), (load.seconds + 60) * 1000);
  return new Promise((res, rej) => {
    child.once('error', (e) => {
      if (e.name !== 'AbortError') rej(e);
    });
    child.once('exit', (code) => {
      clearTimeout(kill);
      if (run) res(run);
      else rej(new Error(`the bots exited with ${code} and no summary:\n${err.slice(-2000)}`));
    });
  });
}
