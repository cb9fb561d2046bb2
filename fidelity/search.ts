// The searches: a shot's strike from several starting spins (the error surface has a basin per
// way the cue ball can meet the first object ball), and the table's constants on fixed strikes.
import type { TableSpec } from '../shared/physics/index.ts';
import type { TrackedShot } from './data.ts';
import { CONSTANTS, constantsOf, firstContactTime, fitStrike, seedStrike, tableWith, type Strike } from './fit.ts';

/** The spins each start is tried at: top -0.3, 0.1, 0.4 R by side -0.3, 0, 0.3 R. */
const SPINS: readonly (readonly [number, number])[] = [-0.3, 0.1, 0.4].flatMap((top) => [-0.3, 0, 0.3].map((side) => [top, side] as const));

/**
 * The best strike for a shot. Starts: `from` (a strike fitted before, e.g. on other constants)
 * as it is, and the nine spins at each of two strikes: the seed from the cue ball's first frames
 * with its heading, speed and t0 fitted to the cue ball's opening run (its tracked samples
 * before the first object ball moves), and `from`. The best is tried again at headings 0.01 and
 * 0.02 rad either side (the first contact's cut is the most sensitive choice), refined, then
 * Nelder-Mead restarted from its result until a restart gains less than 0.1 mm.
 */
export function fitShot(s: TrackedShot, table: TableSpec, from?: Strike): { strike: Strike; rms: number } {
  let best = from ? fitStrike(s, table, from, 150) : { strike: seedStrike(s), rms: Infinity };
  const bases: Strike[] = [openingStrike(s, table)];
  if (from) bases.push(from);
  for (const base of bases) {
    for (const [top, side] of SPINS) {
      const f = fitStrike(s, table, { ...base, top, side }, 60);
      if (f.rms < best.rms) best = f;
    }
  }
  const b = best.strike;
  for (const dh of [-0.02, -0.01, 0.01, 0.02]) {
    const f = fitStrike(s, table, { ...b, heading: b.heading + dh }, 60);
    if (f.rms < best.rms) best = f;
  }
  best = fitStrike(s, table, best.strike, 300);
  for (let k = 0; k < 5; k++) {
    const f = fitStrike(s, table, best.strike, 150);
    const gain = best.rms - f.rms;
    if (f.rms < best.rms) best = f;
    if (!(gain > 1e-4)) break;
  }
  return best;
}

/** The seed with its heading, speed and t0 fitted to the cue ball's run before the first contact. */
function openingStrike(s: TrackedShot, table: TableSpec): Strike {
  const seed = seedStrike(s);
  const until = firstContactTime(s);
  if (!Number.isFinite(until)) return seed;
  const o = fitStrike(s, table, seed, 100, until).strike;
  return { ...seed, heading: o.heading, speed: o.speed, t0: o.t0 };
}

/**
 * The table constants minimising the mean per-shot RMS error over `shots` (each shot's error
 * capped at `cap`, so that a shot the model cannot express does not steer the fit), every strike
 * fitted again in full for each trial: constants and strikes are coupled, and with the strikes
 * held (or refitted only briefly) the constants they were fitted on always look best. A pattern
 * search in the constants' own scales: each constant tried a step up and down in turn, a step
 * kept when it lowers the error; one pass per step size.
 */
export function fitTable(
  shots: readonly TrackedShot[], strikes: readonly Strike[], base: TableSpec, steps: readonly number[],
  onStep?: (message: string) => void, cap = 0.3,
): { table: TableSpec; strikes: Strike[]; mean: number } {
  const trial = (c: number[], from: readonly Strike[]): { c: number[]; strikes: Strike[]; mean: number } => {
    const t = tableWith(base, c);
    if (t === null) return { c, strikes: from.slice(), mean: Infinity };
    const fits = shots.map((s, i) => fitShot(s, t, from[i]));
    return { c, strikes: fits.map((f) => f.strike), mean: fits.reduce((a, f) => a + Math.min(f.rms, cap), 0) / fits.length };
  };
  let best = trial(constantsOf(base), strikes);
  for (const step of steps) {
    for (let k = 0; k < best.c.length; k++) {
      for (const sign of [1, -1]) {
        const c = best.c.slice();
        c[k] = c[k]! * (1 + sign * step);
        const t = trial(c, best.strikes);
        onStep?.(`${CONSTANTS[k]} ${best.c[k]!.toPrecision(3)} -> ${c[k]!.toPrecision(3)}: ${(t.mean * 100).toFixed(2)} cm against ${(best.mean * 100).toFixed(2)}`);
        if (t.mean < best.mean) {
          best = t;
          break;
        }
      }
    }
  }
  return { table: tableWith(base, best.c)!, strikes: best.strikes, mean: best.mean };
}
