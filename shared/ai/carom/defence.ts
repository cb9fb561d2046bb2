// When nothing scores often enough: a stroke that leaves the opponent a hard position. The
// candidates are the coarse search's strokes that hit a ball without a foul (already simulated:
// they cost nothing more); the leaves are ranked by the geometric guess, and the best few are
// probed by simulation where the level looks ahead (the opponent's share of scoring strokes).
import type { Game } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import type { CaromBreadth } from './breadth.ts';
import { geometricEase, probedEase } from './position.ts';
import type { GridTrial } from './search.ts';
import type { Stroke } from './trial.ts';

export interface Defence {
  readonly stroke: Stroke;
  /** The opponent's ease in the position left (0 to 1, lower is better). */
  readonly ease: number;
}

/** Leaves probed when the level probes. */
const PROBED_LEAVES = 4;

export function defence(trials: readonly GridTrial[], b: CaromBreadth, ctx: Context): Defence | null {
  const leaves: { t: GridTrial; next: Game; ease: number }[] = [];
  for (const t of trials) {
    const next = t.next;
    if (next === null || next.verdict?.foul) continue;
    leaves.push({ t, next, ease: geometricEase(next) });
  }
  if (leaves.length === 0) return null;
  leaves.sort((a, c) => a.ease - c.ease);
  if (b.probes === 0) return { stroke: leaves[0]!.t.stroke, ease: leaves[0]!.ease };
  let best: Defence | null = null;
  for (const l of leaves.slice(0, PROBED_LEAVES)) {
    const ease = probedEase(l.next, ctx, b.probeGrid);
    if (best === null || ease < best.ease) best = { stroke: l.t.stroke, ease };
  }
  return best;
}
