// Starts the real server (`server/main.ts`) as a child process, the way `npm start` does after
// its build step, and waits for its `listening on` line.
import { spawn, type ChildProcess } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

export const ROOT = resolve(import.meta.dirname, '../..');

export interface ServerProcess {
  readonly child: ChildProcess;
  readonly url: string;
  stdout(): string;
  stderr(): string;
  /** Sends the signal and resolves with the exit code. */
  stop(signal?: NodeJS.Signals): Promise<number | null>;
}

export interface Exit {
  readonly code: number | null;
  readonly stdout: string;
  readonly stderr: string;
}

export function tempDir(prefix = 'baize-test-'): string {
  return mkdtempSync(join(tmpdir(), prefix));
}

function launch(env: Record<string, string>): { child: ChildProcess; out: string[]; err: string[]; exited: Promise<number | null> } {
  const child = spawn(process.execPath, ['--import', 'tsx', 'server/main.ts'], {
    cwd: ROOT,
    // Every test connects from 127.0.0.1: new players and sockets per address are not limited
    // unless a test says so.
    env: { ...process.env, HOST: '127.0.0.1', PORT: '0', BAIZE_GUESTS_PER_ADDRESS: '1000000000', BAIZE_MAX_SOCKETS_PER_ADDRESS: '100000', ...env },
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  const out: string[] = [];
  const err: string[] = [];
  child.stdout!.setEncoding('utf8').on('data', (d: string) => out.push(d));
  child.stderr!.setEncoding('utf8').on('data', (d: string) => err.push(d));
  const exited = new Promise<number | null>((res) => child.once('exit', (code) => res(code)));
  return { child, out, err, exited };
}

/** Starts a server and resolves once it listens; rejects with its output if it exits first. */
export async function startServerProcess(env: Record<string, string>): Promise<ServerProcess> {
  const { child, out, err, exited } = launch(env);
  const url = await new Promise<string>((res, rej) => {
    const onData = () => {
      const m = /listening on (http:\/\/\S+)/.exec(out.join(''));
      if (m?.[1]) {
        child.stdout!.off('data', onData);
        res(m[1]);
      }
    };
    child.stdout!.on('data', onData);
    void exited.then((code) => rej(new Error(`server exited with ${code} before listening:\n${out.join('')}${err.join('')}`)));
  });
  return {
    child,
    url,
    stdout: () => out.join(''),
    stderr: () => err.join(''),
    async stop(signal: NodeJS.Signals = 'SIGTERM') {
      if (child.exitCode === null) child.kill(signal);
      return exited;
    },
  };
}

/** Runs a server that is expected to exit by itself (a start-up failure). */
export async function runServerToExit(env: Record<string, string>, timeoutMs = 20_000): Promise<Exit> {
  const { child, out, err, exited } = launch(env);
  const timer = setTimeout(() => child.kill('SIGKILL'), timeoutMs);
  const code = await exited;
  clearTimeout(timer);
  return { code, stdout: out.join(''), stderr: err.join('') };
}
