// Refining a scoring stroke to the centre of its scoring region: scan outward from it along the
// heading, then the speed, then the side, each until the stroke stops scoring, and move to the
// middle of the run found. The middle is the stroke the most execution error can miss and still
// score; the run's half-width, in the level's noise sigmas, says how robust it is.
import type { Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { trial, type Stroke } from './trial.ts';

export interface Region {
  /** The centre of the scoring region found. */
  readonly stroke: Stroke;
  /** Half-widths of the region along heading, speed and side, in the level's sigmas. */
  readonly margin: { readonly heading: number; readonly speed: number; readonly side: number };
}

/** Heading scan step, radians, and its limit in steps each way. */
const HEADING_STEP = 0.0015;
const HEADING_STEPS = 16;
/** Speed scan step, as a fraction of the speed. */
const SPEED_STEP = 0.03;
const SPEED_STEPS = 8;
/** Side scan step (fraction of R), and the largest side used (the miscue limit is 0.5). */
const SIDE_STEP = 0.04;
const SIDE_STEPS = 6;
const SIDE_MAX = 0.46;

export function refine(game: Game, seed: Stroke, ctx: Context): Region {
  const scores = (s: Stroke): boolean => trial(game, s, ctx).scored;
  const h = scan((k) => scores({ ...seed, heading: seed.heading + k * HEADING_STEP }), HEADING_STEPS);
  let stroke: Stroke = { ...seed, heading: seed.heading + h.centre * HEADING_STEP };
  const base = stroke;
  const v = scan((k) => scores({ ...base, speed: base.speed * (1 + k * SPEED_STEP) }), SPEED_STEPS);
  stroke = { ...stroke, speed: base.speed * (1 + v.centre * SPEED_STEP) };
  const mid = stroke;
  const maxUp = Math.floor((SIDE_MAX - mid.side) / SIDE_STEP);
  const maxDown = Math.floor((SIDE_MAX + mid.side) / SIDE_STEP);
  const e = scan((k) => (k > maxUp || -k > maxDown ? false : scores({ ...mid, side: mid.side + k * SIDE_STEP })), SIDE_STEPS);
  stroke = { ...stroke, side: mid.side + e.centre * SIDE_STEP };
  const L = ctx.level;
  // The scans are one axis at a time: the centre found may still miss, and then the seed is kept.
  if (!scores(stroke)) return { stroke: seed, margin: { heading: 0.5 * HEADING_STEP / L.heading, speed: 0, side: 0 } };
  return {
    stroke,
    margin: {
      heading: (h.half * HEADING_STEP) / L.heading,
      speed: (v.half * SPEED_STEP) / Math.max(L.speed, 1e-9),
      side: (e.half * SIDE_STEP) / Math.max(L.tip, 1e-9),
    },
  };
}

/** Estimated chance the region holds under noise: each margin as a share of ~2 sigmas, multiplied. */
export function robustness(m: Region['margin']): number {
  const part = (z: number): number => Math.min(1, z / 2);
  return part(m.heading) * part(m.speed) * part(m.side);
}

/**
 * Scan k = 1, 2, ... and k = -1, -2, ... (k = 0 is known to score) up to `limit` each way, stopping
 * each way at the first miss. The centre of the run, in steps, and its half-width (a run of one
 * point has half-width 0.5: it spans half a step each way).
 */
function scan(scores: (k: number) => boolean, limit: number): { centre: number; half: number } {
  let up = 0;
  while (up < limit && scores(up + 1)) up++;
  let down = 0;
  while (down < limit && scores(-(down + 1))) down++;
  return { centre: (up - down) / 2, half: (up + down + 1) / 2 };
}
