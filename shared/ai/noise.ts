// Execution noise: the stroke a player of a level actually plays when aiming at `shot`.
import type { Shot } from '../rules/index.ts';
import { MISCUE_LIMIT } from '../physics/index.ts';
import type { LevelSpec } from './levels.ts';
import type { Random } from './random.ts';

/** Tip offsets are kept inside this share of the miscue limit, noise included. */
const TIP_MARGIN = 0.98;

export function noisy(shot: Shot, level: LevelSpec, random: Random): Shot {
  const heading = shot.heading + level.heading * random.gaussian();
  const speed = Math.max(0.05, shot.speed * (1 + level.speed * random.gaussian()));
  let side = shot.side + level.tip * random.gaussian();
  let top = shot.top + level.tip * random.gaussian();
  const r = Math.sqrt(side * side + top * top);
  const max = MISCUE_LIMIT * TIP_MARGIN;
  if (r > max) {
    side = (side * max) / r;
    top = (top * max) / r;
  }
  return { ...shot, heading, speed, side, top };
}
