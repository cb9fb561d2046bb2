// The searches: a shot's strike from several starting spins (the error surface has a basin per
// way the cue ball can meet the first object ball), and the table's constants on fixed strikes.
import type { TableSpec } from '../shared/physics/index.ts';
import type { TrackedShot } from './data.ts';
import { CONSTANTS, constantsOf, fitStrike, seedStrike, tableWith, type Strike } from './fit.ts';

/** The best strike over starts at three topspins and three sidespins, refined. */
export function fitShot(s: TrackedShot, table: TableSpec, from?: Strike): { strike: Strike; rms: number } {
  const seed = from ?? seedStrike(s);
  let best = from ? fitStrike(s, table, from, 150) : { strike: seed, rms: Infinity };
  for (const top of [-0.3, 0.1, 0.4]) {
    for (const side of [-0.3, 0, 0.3]) {
      const f = fitStrike(s, table, { ...seed, top, side }, 60);
      if (f.rms < best.rms) best = f;
    }
  }
  return fitStrike(s, table, best.strike, 300);
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
