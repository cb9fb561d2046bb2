// How easy a position is for the player on turn: the share of a small grid of strokes that score
// from it (a one-shot look ahead, by simulation), or, where the level does not look ahead, a
// geometric guess: two object balls close together make a large target for the second contact.
import { cueBallId, type Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { coarseHeadings } from './headings.ts';
import { trial } from './trial.ts';

const PROBE_SPEED = 3.5;
const PROBE_SIDES = [-0.3, 0.3];
const PROBE_CUTS = 4;
const TAU = 2 * Math.PI;

/** Share (0 to 1) of about `size` probe strokes that score from `game` for the player on turn. */
export function probedEase(game: Game, ctx: Context, size: number): number {
  if (game.winner !== null) return 0;
  const fan = Math.max(8, Math.floor(size / PROBE_SIDES.length) - 4 * PROBE_CUTS);
  const headings = coarseHeadings(game, TAU / fan, PROBE_CUTS);
  let hits = 0;
  let n = 0;
  for (const side of PROBE_SIDES) {
    for (const heading of headings) {
      n++;
      if (trial(game, { heading, speed: PROBE_SPEED, side, top: 0.2 }, ctx).scored) hits++;
    }
  }
  return n === 0 ? 0 : hits / n;
}

/** A guess (0 to 1) from the layout alone: the closer the shooter's two object balls, the easier. */
export function geometricEase(game: Game): number {
  const cueId = cueBallId(game);
  const objects = game.balls.filter((b) => b.id !== cueId);
  if (objects.length < 2) return 0;
  const [a, b] = objects as [typeof objects[0], typeof objects[0]];
  const d = Math.sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));
  return Math.max(0, 1 - d / 1.6);
}
