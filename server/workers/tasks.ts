// The heavy work that runs off the event loop, as plain data in and out: the computer's decision,
// and the replay of a practice run (up to PRACTICE_MAX_SHOTS shots through the simulation and the
// referee). `runTask` is what a worker thread does with a task; the same function runs in-process
// where no pool is given (unit tests).
import { MiscueError, SimulationInputError } from '../../shared/physics/index.ts';
import { chooseShot, type Decision, type Level } from '../../shared/ai/index.ts';
import { practiceRun, RuleError, type Game, type PracticeKind, type PracticeShot } from '../../shared/rules/index.ts';

export interface ThinkTask {
  readonly type: 'think';
  readonly game: Game;
  readonly level: Level;
  readonly seed: number;
}

export interface PracticeTask {
  readonly type: 'practice';
  readonly kind: PracticeKind;
  readonly player: string;
  readonly seed: number;
  readonly shots: readonly PracticeShot[];
}

/** A practice run as scored: what the API keeps and answers (not every game along the way). */
export interface PracticeScore {
  readonly score: number;
  readonly shots: number;
  readonly achievements: readonly { readonly what: string; readonly player: string; readonly value: number }[];
}

export type Task = ThinkTask | PracticeTask;

/** A task the rules or the physics refuse (a bad shot in a practice run): the caller's fault. */
export class RefusedTask extends Error {
  override readonly name = 'RefusedTask';
}

export function runTask(task: Task): Decision | PracticeScore {
  if (task.type === 'think') return chooseShot(task.game, { level: task.level, seed: task.seed });
  try {
    const run = practiceRun(task.kind, task.player, task.seed, task.shots);
    return { score: run.score, shots: run.games.length, achievements: run.achievements.map((a) => ({ what: a.what, player: a.player, value: a.value })) };
  } catch (err) {
    if (err instanceof RuleError || err instanceof MiscueError || err instanceof SimulationInputError) throw new RefusedTask(err.message);
    throw err;
  }
}
