// The page's side of the computer: its worker's script is fetched once (when the practice page
// opens) and kept as text, so that the worker starts from memory even with the network off.
import type { Decision, Level } from '../../shared/ai/index.ts';
import type { Game } from '../../shared/rules/index.ts';

/** Where the build puts the worker's bundle (scripts/build-client.ts). */
export const WORKER_PATH = '/computer.js';

let script: Promise<string> | null = null;

/** Fetches the worker's script (once); safe to call early and often. */
export function preloadComputer(): Promise<string> {
  script ??= fetch(WORKER_PATH).then((r) => {
    if (!r.ok) throw new Error(`the computer could not be loaded (${r.status})`);
    return r.text();
  });
  script.catch(() => (script = null)); // a later call tries again
  return script;
}

export class ComputerMind {
  private worker: Worker | null = null;
  private nextId = 1;
  private readonly waiting = new Map<number, { resolve(d: Decision): void; reject(e: Error): void }>();

  /** The decision for the player on turn of `game`. */
  async think(game: Game, level: Level, seed: number): Promise<Decision> {
    const worker = await this.start();
    const id = this.nextId++;
    return new Promise<Decision>((resolve, reject) => {
      this.waiting.set(id, { resolve, reject });
      worker.postMessage({ id, game, level, seed });
    });
  }

  stop(): void {
    this.worker?.terminate();
    this.worker = null;
    for (const w of this.waiting.values()) w.reject(new Error('stopped'));
    this.waiting.clear();
  }

  private async start(): Promise<Worker> {
    if (this.worker) return this.worker;
    const text = await preloadComputer();
    const url = URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
    const worker = new Worker(url);
    URL.revokeObjectURL(url);
    worker.onmessage = (e: MessageEvent<{ id: number; decision?: Decision; error?: string }>) => {
      const w = this.waiting.get(e.data.id);
      this.waiting.delete(e.data.id);
      if (e.data.decision) w?.resolve(e.data.decision);
      else w?.reject(new Error(e.data.error ?? 'no decision'));
    };
    worker.onerror = (e) => {
      for (const w of this.waiting.values()) w.reject(new Error(e.message));
      this.waiting.clear();
    };
    this.worker = worker;
    return worker;
  }
}
