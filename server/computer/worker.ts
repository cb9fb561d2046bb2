// One computer's mind in a worker thread: takes { id, game, level, seed }, answers chooseShot's
// decision (or the error's message). Bundled by pool.ts, so it runs the same under tsx and npm start.
import { setPriority } from 'node:os';
import { parentPort } from 'node:worker_threads';
import { chooseShot, type Level } from '../../shared/ai/index.ts';
import type { Game } from '../../shared/rules/index.ts';

export interface ThinkRequest {
  readonly id: number;
  readonly game: Game;
  readonly level: Level;
  readonly seed: number;
}

// Thinking yields the CPU to the event loop: on Linux, setpriority() on "this process" (0) sets
// the nice value of the calling thread only, so the server's main thread keeps its priority.
try {
  setPriority(0, 19);
} catch {
  // Not allowed here (another OS): the thread thinks at normal priority.
}

parentPort!.on('message', (req: ThinkRequest) => {
  try {
    const decision = chooseShot(req.game, { level: req.level, seed: req.seed });
    parentPort!.postMessage({ id: req.id, decision });
  } catch (err) {
    parentPort!.postMessage({ id: req.id, error: (err as Error).message ?? String(err) });
  }
});
