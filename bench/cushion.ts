// npm run bench:cushion — speed against error of the cushion kernel at each tolerance and of
// the anchors' scheme (bench/cushion-anchor.ts), timed side by side in one run on the same
// impacts, paper constants: the grid of 528 (tests/support/cushion-cases.ts, benchGrid), then
// 528 random draws over the range (benchRandom), then 528 balls rolling into the cushion
// with a little sidespin (benchRolling, the commonest hit in play). Errors are against the converged
// reference (tests/support/cushion-reference.ts), as a fraction of V0, over every component
// (spins times R). Prints a markdown table for each set.
//
// Time per impact: each impact is solved REPS times in a row and timed; rounds interleave the
// settings impact by impact, so that all see the same machine state; an impact's time is its
// median over the rounds. The table gives the median over impacts (the measure) and the
// mean (what a mix of impacts like the set costs), each with its ratio to the anchors'.
import { CUSHION_TOLERANCES } from '../shared/physics/index.ts';
import { CushionKernel } from '../shared/physics/cushion/index.ts';
import type { CushionParams, CushionState } from '../shared/physics/index.ts';
import { benchGrid, benchRandom, benchRolling, PAPER, relError } from '../tests/support/cushion-cases.ts';
import type { GridCase } from '../tests/support/cushion-cases.ts';
import { referenceRebound } from '../tests/support/cushion-reference.ts';
import { anchorRebound } from './cushion-anchor.ts';

type Solver = (s: CushionState, p: CushionParams) => CushionState;

// The kernel as the simulation calls it: one solver kept for many impacts (CushionKernel).
const kernel = new CushionKernel();
const settings: { name: string; solve: Solver }[] = [
  ...Object.entries(CUSHION_TOLERANCES).map(([name, tol]) => ({
    name: `kernel, ${name} (tolerance ${tol})`,
    solve: ((s, p) => kernel.rebound(s, p, { tolerance: name as keyof typeof CUSHION_TOLERANCES })) as Solver,
  })),
  { name: 'anchors\' scheme (Euler, 100 steps, floor 0.001 N s)', solve: anchorRebound },
];

const REPS = 25;
const ROUNDS = 9;
let sink = 0;
/** Microseconds per solve of one impact, over REPS solves in a row. */
function timeOne(solve: Solver, s: CushionState): number {
  const t = performance.now();
  for (let r = 0; r < REPS; r++) sink += solve(s, PAPER).vx;
  return ((performance.now() - t) * 1000) / REPS;
}
const median = (a: readonly number[]): number => [...a].sort((x, y) => x - y)[a.length >> 1]!;
const mean = (a: readonly number[]): number => a.reduce((x, y) => x + y, 0) / a.length;

/** Times every setting on the cases and prints the table (and, for the grid, its speeds apart). */
function table(title: string, cases: readonly GridCase[], bySpeed = false): void {
  const states = cases.map((g) => g.state);
  process.stdout.write(`Reference solutions for ${cases.length} impacts... `);
  const t0 = performance.now();
  const refs = cases.map((g) => referenceRebound(g.state, PAPER).state);
  process.stdout.write(`${((performance.now() - t0) / 1000).toFixed(1)} s\n\n`);
  const errorsOf = (solve: Solver): number[] => cases.map((g, i) => relError(solve(g.state, PAPER), refs[i]!, PAPER.R, g.V0));
  const errors = (solve: Solver): { max: number; median: number } => {
    const e = errorsOf(solve).sort((a, b) => a - b);
    return { max: e[e.length - 1]!, median: e[e.length >> 1]! };
  };
  // Warm-up (JIT), then the rounds, the settings interleaved impact by impact.
  for (const s of settings) for (let r = 0; r < 20; r++) for (const st of states) sink += s.solve(st, PAPER).vx;
  const samples: number[][][] = settings.map(() => states.map(() => []));
  for (let round = 0; round < ROUNDS; round++) {
    states.forEach((st, i) => settings.forEach((s, k) => samples[k]![i]!.push(timeOne(s.solve, st))));
  }
  const perImpact = samples.map((bySetting) => bySetting.map(median));
  const medians = perImpact.map(median);
  const means = perImpact.map(mean);
  const anchor = settings.length - 1;
  console.log(`${title}, paper constants, Node ${process.version}.`);
  console.log(`Time per impact: median of ${ROUNDS} rounds of ${REPS} solves in a row. Error: |component - reference| / V0 (spins × R).\n`);
  console.log('| setting | median µs per impact | speed vs anchors (medians) | mean µs per impact | speed vs anchors (means) | max error | median error |');
  console.log('|---|---|---|---|---|---|---|');
  settings.forEach((s, i) => {
    const e = errors(s.solve);
    console.log(`| ${s.name} | ${medians[i]!.toFixed(2)} | ${(medians[anchor]! / medians[i]!).toFixed(1)}× | ` +
      `${means[i]!.toFixed(2)} | ${(means[anchor]! / means[i]!).toFixed(1)}× | ${e.max.toExponential(1)} | ${e.median.toExponential(1)} |`);
  });
  console.log('');
  if (bySpeed) speeds(cases, perImpact[0]!, perImpact[anchor]!, errorsOf(settings[anchor]!.solve));
}

/**
 * The grid's speeds apart, for the default setting (kernel: the per-impact times of the first
 * setting) and the anchors: the kernel's cost does not depend on V0 (the model is homogeneous in
 * the speeds), the anchors' does (their step is floored at 0.001 N s, so an impact at 0.05 m/s
 * takes a handful of steps, and a badly wrong one). The row before the whole grid's leaves out
 * the slowest speed: without it the anchors' largest and median errors are those that
 * are reported for the anchors on a grid of 528 impacts (about 2e-2 and 3e-3), which 0.05 m/s
 * takes to 2.4e-1.
 */
function speeds(cases: readonly GridCase[], kernel: readonly number[], anchors: readonly number[], anchorErr: readonly number[]): void {
  console.log('The grid by speed (kernel at its default setting):\n');
  console.log('| V0 m/s | impacts | kernel median µs | anchors median µs | speed vs anchors (medians) | anchors\' max error | anchors\' median error |');
  console.log('|---|---|---|---|---|---|---|');
  const row = (name: string, keep: (g: GridCase) => boolean): void => {
    const idx = cases.map((_, i) => i).filter((i) => keep(cases[i]!));
    const k = median(idx.map((i) => kernel[i]!));
    const a = median(idx.map((i) => anchors[i]!));
    const e = idx.map((i) => anchorErr[i]!);
    console.log(`| ${name} | ${idx.length} | ${k.toFixed(2)} | ${a.toFixed(2)} | ${(a / k).toFixed(1)}× | ` +
      `${Math.max(...e).toExponential(1)} | ${median(e).toExponential(1)} |`);
  };
  for (const V0 of [...new Set(cases.map((g) => g.V0))]) row(String(V0), (g) => g.V0 === V0);
  const slowest = Math.min(...cases.map((g) => g.V0));
  row(`all but ${slowest}`, (g) => g.V0 !== slowest);
  row('all', () => true);
  console.log('');
}

const grid = benchGrid(PAPER.R);
table(`Cushion impacts, the grid: ${grid.length} (incidence 0.5-89.5°, V0 0.05-5 m/s, topspin k -1..2, sidespin k -2..2)`, grid, true);
const draws = benchRandom(PAPER.R);
table(`Cushion impacts, random draws: ${draws.length} uniform over the same range (seed 2026)`, draws);
const rolling = benchRolling(PAPER.R);
table(`Cushion impacts, rolling balls: ${rolling.length} with natural roll (k_T = 1), V0 0.05-5 m/s, α 0.5-89.5°, sidespin k -0.5..0.5 (seed 2027)`, rolling);
if (sink === 42) console.log('');
