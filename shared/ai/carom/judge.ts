// Judging strokes as they would be played: `samples` noisy copies of each, simulated and refereed.
// Every stroke is judged with the same noise draws (common random numbers), so that two strokes
// are compared on the same luck and the difference between them is the strokes' own.
import type { Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { Random } from '../random.ts';
import { trial, type Stroke } from './trial.ts';

export interface Judged {
  readonly stroke: Stroke;
  /** Share of the noisy samples that scored. */
  readonly rate: number;
}

export function judge(game: Game, strokes: readonly Stroke[], samples: number, ctx: Context): Judged[] {
  const seed = Math.floor(ctx.random.uniform() * 0x100000000);
  return strokes.map((stroke) => {
    const noise = new Random(seed);
    let hits = 0;
    for (let i = 0; i < samples; i++) if (trial(game, stroke, ctx, noise).scored) hits++;
    return { stroke, rate: samples === 0 ? 0 : hits / samples };
  });
}
