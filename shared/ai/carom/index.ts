// Three-cushion: the computer's choice of stroke. A coarse search over headings (thin to thick on
// both object balls, and all round for bank-first paths), speeds, side and top, each simulated
// without noise; the widest scoring regions refined to their centres; the most robust of those
// judged under the level's noise through the real simulation and referee, with the position each
// leaves looked at; and, when nothing scores often enough, a defensive stroke.
import type { Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { LEVELS } from '../levels.ts';
import type { Decision, Level } from '../types.ts';
import { CAROM_BREADTH, type CaromBreadth } from './breadth.ts';
import { defence } from './defence.ts';
import { judge, type Judged } from './judge.ts';
import { geometricEase, probedEase } from './position.ts';
import { refine, robustness } from './refine.ts';
import { coarseSearch, scoringSeeds } from './search.ts';
import { shotOf, trial, type Stroke } from './trial.ts';

export { CAROM_BREADTH } from './breadth.ts';
export type { CaromBreadth } from './breadth.ts';

/** Below this share of noisy samples scoring, a defensive stroke is preferred when one exists. */
const DEFENCE_BELOW = 0.25;
/** Weight of the position left after a point, against the chance of the point. */
const POSITION_WEIGHT = 0.3;

export function chooseCaromShot(game: Game, ctx: Context, level?: Level): Decision {
  const b = breadthOf(ctx, level);
  const grid = coarseSearch(game, ctx, b);
  const seeds = scoringSeeds(grid, b, b.regions);
  const regions = seeds.map((s) => refine(game, s.stroke, ctx));
  regions.sort((x, y) => robustness(y.margin) - robustness(x.margin));
  const judged = judge(game, regions.slice(0, b.judged).map((r) => r.stroke), b.samples, ctx);
  const attack = bestAttack(game, judged, b, ctx);
  if (attack === null || attack.rate < DEFENCE_BELOW) {
    const safe = defence(grid.trials, b, ctx);
    if (safe !== null) return { shot: shotOf(game, safe.stroke) };
  }
  if (attack !== null) return { shot: shotOf(game, attack.stroke) };
  return { shot: shotOf(game, fallback(grid.trials)) };
}

/** The level's breadth: by the level number when given, else the level whose spec the context holds. */
function breadthOf(ctx: Context, level?: Level): CaromBreadth {
  if (level !== undefined) return CAROM_BREADTH[level];
  for (const n of [1, 2, 3, 4, 5] as const) if (LEVELS[n] === ctx.level) return CAROM_BREADTH[n];
  // A spec of its own (a test's): the breadth of the level whose heading noise is nearest above.
  for (const n of [5, 4, 3, 2] as const) if (ctx.level.heading <= LEVELS[n].heading) return CAROM_BREADTH[n];
  return CAROM_BREADTH[1];
}

/** The judged stroke with the best chance of a point, the position it leaves weighing in. */
function bestAttack(game: Game, judged: readonly Judged[], b: CaromBreadth, ctx: Context): Judged | null {
  const ranked = judged.filter((j) => j.rate > 0).sort((x, y) => y.rate - x.rate);
  if (ranked.length === 0) return null;
  let best: { j: Judged; value: number } | null = null;
  ranked.forEach((j, i) => {
    const look = i < b.probes ? lookAhead(game, j.stroke, b, ctx) : 0;
    const value = j.rate * (1 + POSITION_WEIGHT * look);
    if (best === null || value > best.value) best = { j, value };
  });
  return best!.j;
}

/** The ease (0 to 1) of the position a stroke played as aimed leaves the shooter after a point. */
function lookAhead(game: Game, stroke: Stroke, b: CaromBreadth, ctx: Context): number {
  const after = trial(game, stroke, ctx).next;
  if (after === null || after.turn !== game.turn) return 0;
  return b.probeGrid > 0 ? Math.min(1, 4 * probedEase(after, ctx, b.probeGrid)) : geometricEase(after);
}

/** A stroke the rules accepted in the search (any will do: nothing scores and nothing is safe). */
function fallback(trials: readonly { stroke: Stroke; next: Game | null }[]): Stroke {
  const ok = trials.find((t) => t.next !== null);
  return ok ? ok.stroke : { heading: 0, speed: 2, side: 0, top: 0 };
}
