// The coarse search: every heading of coarseHeadings at every speed, side and top of the level's
// grid, simulated without noise. A scoring stroke whose grid neighbours also score lies inside a
// wide scoring region: those are the seeds worth refining.
import type { Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import type { CaromBreadth } from './breadth.ts';
import { coarseHeadings } from './headings.ts';
import { trial, type Stroke, type Trial } from './trial.ts';

export interface GridTrial extends Trial {
  readonly stroke: Stroke;
  /** Indices in the grid: heading, speed, side, top. */
  readonly at: readonly [number, number, number, number];
}

export interface Grid {
  readonly headings: readonly number[];
  readonly trials: readonly GridTrial[];
}

export function coarseSearch(game: Game, ctx: Context, b: CaromBreadth): Grid {
  const headings = coarseHeadings(game, b.headingStep, b.cuts);
  const trials: GridTrial[] = [];
  for (let t = 0; t < b.tops.length; t++) {
    for (let e = 0; e < b.sides.length; e++) {
      for (let s = 0; s < b.speeds.length; s++) {
        for (let h = 0; h < headings.length; h++) {
          const stroke = { heading: headings[h]!, speed: b.speeds[s]!, side: b.sides[e]!, top: b.tops[t]! };
          ctx.stats.candidates++;
          trials.push({ ...trial(game, stroke, ctx), stroke, at: [h, s, e, t] });
        }
      }
    }
  }
  return { headings, trials };
}

/**
 * The scoring strokes, widest region first: each rated by how many of its neighbours in the grid
 * (heading +-1 and +-2, speed +-1, side +-1) also score. Ties keep grid order (deterministic).
 */
export function scoringSeeds(grid: Grid, b: CaromBreadth, count: number): GridTrial[] {
  const H = grid.headings.length;
  const S = b.speeds.length;
  const E = b.sides.length;
  const index = (h: number, s: number, e: number, t: number): number => ((t * E + e) * S + s) * H + h;
  const scores = (h: number, s: number, e: number, t: number): boolean => {
    if (s < 0 || s >= S || e < 0 || e >= E) return false;
    return grid.trials[index(((h % H) + H) % H, s, e, t)]!.scored;
  };
  const rated: { t: GridTrial; n: number }[] = [];
  for (const g of grid.trials) {
    if (!g.scored) continue;
    const [h, s, e, t] = g.at;
    let n = 0;
    for (const dh of [-2, -1, 1, 2]) if (scores(h + dh, s, e, t)) n += 2;
    for (const ds of [-1, 1]) if (scores(h, s + ds, e, t)) n += 1;
    for (const de of [-1, 1]) if (scores(h, s, e + de, t)) n += 1;
    rated.push({ t: g, n });
  }
  rated.sort((a, c) => c.n - a.n);
  // One seed per heading run: a neighbour of a chosen seed at the same speed and side adds nothing.
  const out: GridTrial[] = [];
  for (const r of rated) {
    if (out.length >= count) break;
    const [h, s, e, t] = r.t.at;
    const near = out.some((o) => o.at[1] === s && o.at[2] === e && o.at[3] === t && Math.min(Math.abs(o.at[0] - h), H - Math.abs(o.at[0] - h)) <= 2);
    if (!near) out.push(r.t);
  }
  return out;
}
