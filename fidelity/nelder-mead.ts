// The Nelder-Mead simplex method (Nelder and Mead, The Computer Journal 7 (1965) 308-313), with
// the standard coefficients (reflection 1, expansion 2, contraction 1/2, shrink 1/2): derivative-
// free, robust to the kinks an event-driven simulation puts in an error surface.

export interface Minimum {
  readonly x: number[];
  readonly f: number;
  readonly evaluations: number;
}

/** Minimises f from x0 with initial steps `step` per coordinate, within `maxEvaluations`. */
export function nelderMead(f: (x: number[]) => number, x0: readonly number[], step: readonly number[], maxEvaluations: number, fTol = 1e-9): Minimum {
  const n = x0.length;
  let evaluations = 0;
  const value = (x: number[]): number => {
    evaluations++;
    const v = f(x);
    return Number.isFinite(v) ? v : Infinity;
  };
  const simplex = [x0.slice()];
  for (let i = 0; i < n; i++) {
    const x = x0.slice();
    x[i]! += step[i]!;
    simplex.push(x);
  }
  let fs = simplex.map(value);
  while (evaluations < maxEvaluations) {
    const order = fs.map((_, i) => i).sort((a, b) => fs[a]! - fs[b]!);
    const s = order.map((i) => simplex[i]!);
    fs = order.map((i) => fs[i]!);
    simplex.splice(0, simplex.length, ...s);
    if (Math.abs(fs[n]! - fs[0]!) <= fTol) break;
    const centroid = Array.from({ length: n }, (_, j) => simplex.slice(0, n).reduce((a, x) => a + x[j]!, 0) / n);
    const along = (k: number): number[] => centroid.map((c, j) => c + k * (c - simplex[n]![j]!));
    const xr = along(1);
    const fr = value(xr);
    if (fr < fs[0]!) {
      const xe = along(2);
      const fe = value(xe);
      [simplex[n], fs[n]] = fe < fr ? [xe, fe] : [xr, fr];
    } else if (fr < fs[n - 1]!) {
      [simplex[n], fs[n]] = [xr, fr];
    } else {
      const xc = fr < fs[n]! ? along(0.5) : along(-0.5);
      const fc = value(xc);
      if (fc < Math.min(fr, fs[n]!)) {
        [simplex[n], fs[n]] = [xc, fc];
      } else {
        for (let i = 1; i <= n; i++) {
          simplex[i] = simplex[i]!.map((v, j) => simplex[0]![j]! + 0.5 * (v - simplex[0]![j]!));
          fs[i] = value(simplex[i]!);
        }
      }
    }
  }
  const best = fs.indexOf(Math.min(...fs));
  return { x: simplex[best]!, f: fs[best]!, evaluations };
}
