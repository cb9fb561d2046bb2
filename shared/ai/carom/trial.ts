// One stroke tried from a position: simulated by shared/physics and judged by the referee (the
// real playShot), with or without the level's execution noise. A stroke the rules refuse, or a
// miscue, is null.
import { cueBallId, playShot, type Game, type Shot } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { noisy } from '../noise.ts';
import type { Random } from '../random.ts';

/** A stroke without its player and ball: what the search varies. */
export interface Stroke {
  readonly heading: number;
  readonly speed: number;
  readonly side: number;
  readonly top: number;
}

export interface Trial {
  /** The game after the stroke, or null when the stroke was refused. */
  readonly next: Game | null;
  /** Whether the shooter scored (a point, or the game). */
  readonly scored: boolean;
}

export function shotOf(game: Game, stroke: Stroke): Shot {
  return { player: game.turn, ball: cueBallId(game), heading: stroke.heading, speed: stroke.speed, side: stroke.side, top: stroke.top };
}

export function trial(game: Game, stroke: Stroke, ctx: Context, noise?: Random): Trial {
  ctx.stats.simulations++;
  const shot = shotOf(game, stroke);
  let next: Game;
  try {
    next = playShot(game, noise ? noisy(shot, ctx.level, noise) : shot).game;
  } catch {
    return { next: null, scored: false };
  }
  const me = game.turn;
  const scored = next.winner === me || (next.scores[me] ?? 0) > (game.scores[me] ?? 0);
  return { next, scored };
}
