// One worker thread of the pool (pool.ts): takes { id, task }, answers { id, result } or
// { id, error, refused } (refused: the rules or the physics turned the task down). Bundled by
// pool.ts, so it runs the same under tsx and npm start.
import { setPriority } from 'node:os';
import { parentPort } from 'node:worker_threads';
import { RefusedTask, runTask, type Task } from './tasks.ts';

// The work yields the CPU to the event loop: on Linux, setpriority() on "this process" (0) sets
// the nice value of the calling thread only, so the server's main thread keeps its priority.
try {
  setPriority(0, 19);
} catch {
  // Not allowed here (another OS): the thread works at normal priority.
}

parentPort!.on('message', (req: { id: number; task: Task }) => {
  try {
    parentPort!.postMessage({ id: req.id, result: runTask(req.task) });
  } catch (err) {
    parentPort!.postMessage({ id: req.id, error: (err as Error).message ?? String(err), refused: err instanceof RefusedTask });
  }
});
