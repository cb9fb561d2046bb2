// Speed against error, live, for the edited impact: the kernel at each named tolerance and the
// anchors' 100-step Euler scheme (bench/cushion-anchor.ts), timed side by side here, each error
// against the converged solution (the kernel at its finest tolerance), as a fraction of V0.
import { anchorRebound } from '../../bench/cushion-anchor.ts';
import { cushionRebound, CUSHION_TOLERANCES } from '../../shared/physics/index.ts';
import type { CushionParams, CushionState } from '../../shared/physics/index.ts';

export interface SpeedRow {
  readonly name: string;
  /** Microseconds per impact. */
  readonly us: number;
  /** Largest component's error / V0 (spins times R). */
  readonly error: number;
}

const FINEST = 1e-12;

/**
 * Microseconds per call of each solver: the best batch of five rounds that take the solvers in
 * turn (so that none is timed while the engine is still compiling the shared code), each batch
 * long enough for the browser's coarse clock.
 */
function timeAll(solvers: readonly (() => void)[]): number[] {
  const sizes = solvers.map((solve) => {
    let n = 16;
    for (;;) {
      const t0 = performance.now();
      for (let i = 0; i < n; i++) solve();
      if (performance.now() - t0 >= 4 || n >= 8192) return n;
      n *= 2;
    }
  });
  const best = solvers.map(() => Infinity);
  for (let round = 0; round < 5; round++) {
    solvers.forEach((solve, k) => {
      const t0 = performance.now();
      for (let i = 0; i < sizes[k]!; i++) solve();
      best[k] = Math.min(best[k]!, ((performance.now() - t0) * 1000) / sizes[k]!);
    });
  }
  return best;
}

export function speedRows(s: CushionState, p: CushionParams): SpeedRow[] {
  const V0 = Math.hypot(s.vx, s.vy);
  const ref = cushionRebound(s, p, { tolerance: FINEST });
  const error = (o: CushionState): number =>
    Math.max(Math.abs(o.vx - ref.vx), Math.abs(o.vy - ref.vy), p.R * Math.abs(o.wx - ref.wx), p.R * Math.abs(o.wy - ref.wy), p.R * Math.abs(o.wz - ref.wz)) / V0;
  const solvers: { name: string; solve: () => CushionState }[] = [
    ...Object.entries(CUSHION_TOLERANCES).map(([name, tol]) => ({ name: `kernel, ${name} (${tol})`, solve: () => cushionRebound(s, p, { tolerance: tol }) })),
    { name: 'anchors\' scheme (Euler, 100 steps)', solve: () => anchorRebound(s, p) },
  ];
  const us = timeAll(solvers.map((x) => x.solve));
  return solvers.map((x, k) => ({ name: x.name, us: us[k]!, error: error(x.solve()) }));
}

/** A horizontal bar chart of the times, each bar labelled with its error. */
export function speedChartSvg(rows: readonly SpeedRow[]): string {
  const w = 640;
  const bar = 22;
  const left = 250;
  const max = Math.max(...rows.map((r) => r.us), 1e-9);
  const h = rows.length * (bar + 8) + 30;
  const parts = rows.map((r, i) => {
    const y = 10 + i * (bar + 8);
    const len = ((w - left - 150) * r.us) / max; // room for the value after the longest bar
    return `<text x="${left - 8}" y="${y + 15}" text-anchor="end" font-size="12">${r.name}</text>` +
      `<rect data-bar="${r.name}" x="${left}" y="${y}" width="${len.toFixed(1)}" height="${bar}" fill="${i === rows.length - 1 ? '#d62728' : '#1f77b4'}"><title>${r.us.toFixed(2)} µs, error ${r.error.toExponential(1)} V0</title></rect>` +
      `<text x="${(left + len + 6).toFixed(1)}" y="${y + 15}" font-size="11">${r.us.toFixed(1)} µs, ${r.error.toExponential(1)} V0</text>`;
  });
  // On white, as the lab's other figures are.
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}" font-family="Helvetica, Arial, sans-serif"><rect width="${w}" height="${h}" fill="#fff"/>${parts.join('')}` +
    `<text x="${left}" y="${h - 4}" font-size="11" fill="#555">time per impact (µs); label: error against the converged solution</text></svg>`;
}
