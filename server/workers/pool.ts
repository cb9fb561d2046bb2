// A small pool of worker threads for the heavy work (tasks.ts): the computer's search of thousands
// of simulations and the replay of practice runs never run on the event loop. The worker is bundled
// by esbuild on the first task (Node's workers do not inherit tsx's loader), which works alike under
// `node --import tsx` and npm start. A task that runs past its budget has its worker terminated
// (and replaced) and is rejected; so is a task whose worker crashes. Tasks wait their turn in one
// queue, first come first served.
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
import { Worker } from 'node:worker_threads';
import type { Decision } from '../../shared/ai/index.ts';
import { RefusedTask, runTask, type PracticeScore, type PracticeTask, type Task, type ThinkTask } from './tasks.ts';

/** What the game service needs of the pool (a fake in unit tests). */
export interface Thinker {
  think(task: Omit<ThinkTask, 'type'>): Promise<Decision>;
  close(): Promise<void>;
}

/** What the API needs of the pool: a practice run replayed and scored (RefusedTask for a bad shot). */
export interface PracticeScorer {
  scorePractice(task: Omit<PracticeTask, 'type'>): Promise<PracticeScore>;
}

/** Practice runs scored on the calling thread: for tests and tools that start no pool. */
export const IN_PROCESS: PracticeScorer = {
  scorePractice: async (task) => runTask({ type: 'practice', ...task }) as PracticeScore,
};

export interface PoolOptions {
  /** Worker threads. */
  readonly size: number;
  /** Longest a task may run in a worker before it is given up (ms). */
  readonly budgetMs: number;
  readonly log?: (line: string) => void;
}

interface Pending {
  readonly id: number;
  readonly task: Task;
  resolve(result: unknown): void;
  reject(e: Error): void;
}

interface Slot {
  worker: Worker;
  busy: Pending | null;
  timer?: NodeJS.Timeout;
}

/** The wait before a crashed worker is replaced (ms). */
const RESPAWN_MS = 1000;
const WORKER_SOURCE = fileURLToPath(new URL('./worker.ts', import.meta.url));

/**
 * Bundles the worker in memory, as a data: URL the threads start from: no file is left behind,
 * even by a killed process. (The worker imports nothing but Node's built-ins and shared/.)
 */
async function bundleWorker(): Promise<URL> {
  const out = await build({ entryPoints: [WORKER_SOURCE], write: false, bundle: true, platform: 'node', format: 'esm', target: 'node20', packages: 'external', logLevel: 'warning' });
  return new URL(`data:text/javascript;base64,${Buffer.from(out.outputFiles[0]!.contents).toString('base64')}`);
}

export class WorkerPool implements Thinker, PracticeScorer {
  private readonly slots: Slot[] = [];
  private readonly queue: Pending[] = [];
  private nextId = 1;
  private closed = false;
  private readonly log: (line: string) => void;
  private started = false;
  private file: URL | undefined;

  constructor(private readonly options: PoolOptions) {
    this.log = options.log ?? ((line) => console.error(line));
  }

  /** Builds the worker and starts the threads on the first task: a server given no heavy work keeps neither. */
  private start(): void {
    if (this.started) return;
    this.started = true;
    bundleWorker().then(
      (file) => {
        this.file = file;
        for (let i = 0; i < this.options.size && !this.closed; i++) this.slots.push(this.spawn());
        this.pump();
      },
      (err: unknown) => {
        this.log(`workers: the worker could not be built: ${(err as Error).message}`);
        for (const p of this.queue.splice(0)) p.reject(new Error('no worker'));
      },
    );
  }

  /** Tasks waiting for a worker and running. */
  get load(): number {
    return this.queue.length + this.slots.filter((s) => s.busy).length;
  }

  think(task: Omit<ThinkTask, 'type'>): Promise<Decision> {
    return this.run({ type: 'think', ...task }) as Promise<Decision>;
  }

  scorePractice(task: Omit<PracticeTask, 'type'>): Promise<PracticeScore> {
    return this.run({ type: 'practice', ...task }) as Promise<PracticeScore>;
  }

  private run(task: Task): Promise<unknown> {
    if (this.closed) return Promise.reject(new Error('the pool is closed'));
    this.start();
    return new Promise<unknown>((resolve, reject) => {
      this.queue.push({ id: this.nextId++, task, resolve, reject });
      this.pump();
    });
  }

  async close(): Promise<void> {
    this.closed = true;
    for (const p of this.queue.splice(0)) p.reject(new Error('the pool is closed'));
    await Promise.all(
      this.slots.map((s) => {
        clearTimeout(s.timer);
        s.busy?.reject(new Error('the pool is closed'));
        s.busy = null;
        return s.worker.terminate();
      }),
    );
  }

  private spawn(): Slot {
    const slot: Slot = { worker: new Worker(this.file!), busy: null };
    slot.worker.unref();
    slot.worker.on('message', (m: { id: number; result?: unknown; error?: string; refused?: boolean }) => {
      const p = slot.busy;
      if (!p || p.id !== m.id) return;
      clearTimeout(slot.timer);
      slot.busy = null;
      if (m.error === undefined) p.resolve(m.result);
      else p.reject(m.refused ? new RefusedTask(m.error) : new Error(m.error));
      this.pump();
    });
    slot.worker.on('error', (err) => this.replace(slot, `crashed: ${err.message}`));
    slot.worker.on('exit', (code) => {
      if (!this.closed && this.slots.includes(slot)) this.replace(slot, `exited with ${code}`);
    });
    return slot;
  }

  /** Gives up the slot's task and puts a fresh worker in its place. */
  private replace(slot: Slot, why: string, timedOut = false): void {
    const i = this.slots.indexOf(slot);
    if (i < 0) return;
    clearTimeout(slot.timer);
    const p = slot.busy;
    slot.busy = null;
    this.slots.splice(i, 1);
    void slot.worker.terminate();
    this.log(`workers: a worker ${why}`);
    p?.reject(new Error(`the worker ${why}`));
    // A worker given up for its budget is replaced at once; one that crashed a second later, so
    // that a worker failing as it starts cannot spin.
    const respawn = () => {
      if (this.closed) return;
      this.slots.push(this.spawn());
      this.pump();
    };
    if (timedOut) respawn();
    else setTimeout(respawn, RESPAWN_MS).unref();
    this.pump();
  }

  private pump(): void {
    if (this.file === undefined) return;
    for (const slot of this.slots) {
      if (slot.busy || this.queue.length === 0) continue;
      const p = this.queue.shift()!;
      slot.busy = p;
      slot.timer = setTimeout(() => this.replace(slot, `took longer than ${this.options.budgetMs} ms`, true), this.options.budgetMs);
      slot.timer.unref();
      try {
        slot.worker.postMessage({ id: p.id, task: p.task });
      } catch (err) {
        // A task that cannot be sent (not plain data) frees its worker at once.
        clearTimeout(slot.timer);
        slot.busy = null;
        p.reject(err as Error);
      }
    }
  }
}
