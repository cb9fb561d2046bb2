// A candidate tried as it would be played: placed, struck with the level's noise, simulated and
// judged by the referee. A stroke the rules refuse (or a miscue) is null.
import { playShot, type Game, type Point, type Shot } from '../rules/index.ts';
import type { Context } from './context.ts';
import { noisy } from './noise.ts';

export function tryShot(game: Game, shot: Shot, cueBall: Point | undefined, ctx: Context, withNoise = true): Game | null {
  ctx.stats.simulations++;
  try {
    return playShot(game, withNoise ? noisy(shot, ctx.level, ctx.random) : shot, cueBall).game;
  } catch {
    return null;
  }
}
