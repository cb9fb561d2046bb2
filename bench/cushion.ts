// npm run bench:cushion — speed against error of the cushion kernel at each tolerance and of
// the anchors' scheme (bench/cushion-anchor.ts), timed side by side in one run on the same
// 528 impacts (tests/support/cushion-cases.ts, benchGrid), paper constants. Errors are against
// the converged reference (tests/support/cushion-reference.ts), as a fraction of V0, over every
// component (spins times R). Prints a markdown table.
//
// Time per impact: each impact is solved REPS times in a row and timed; rounds interleave the
// settings impact by impact, so that all see the same machine state; an impact's time is its
// median over the rounds. The table gives the median over impacts (the measure) and the
// mean (what a mix of impacts like this grid costs), each with its ratio to the anchors'.
import { cushionRebound, CUSHION_TOLERANCES } from '../shared/physics/index.ts';
import type { CushionParams, CushionState } from '../shared/physics/index.ts';
import { benchGrid, PAPER, relError } from '../tests/support/cushion-cases.ts';
import { referenceRebound } from '../tests/support/cushion-reference.ts';
import { anchorRebound } from './cushion-anchor.ts';

type Solver = (s: CushionState, p: CushionParams) => CushionState;

const grid = benchGrid(PAPER.R);
const states = grid.map((g) => g.state);

const settings: { name: string; solve: Solver }[] = [
  ...Object.entries(CUSHION_TOLERANCES).map(([name, tol]) => ({
    name: `kernel, ${name} (tolerance ${tol})`,
    solve: ((s, p) => cushionRebound(s, p, { tolerance: name as keyof typeof CUSHION_TOLERANCES })) as Solver,
  })),
  { name: 'anchors\' scheme (Euler, 100 steps, floor 0.001 N s)', solve: anchorRebound },
];

process.stdout.write(`Reference solutions for ${grid.length} impacts... `);
const t0 = performance.now();
const refs = grid.map((g) => referenceRebound(g.state, PAPER).state);
process.stdout.write(`${((performance.now() - t0) / 1000).toFixed(1)} s\n\n`);

function errors(solve: Solver): { max: number; median: number } {
  const e = grid.map((g, i) => relError(solve(g.state, PAPER), refs[i]!, PAPER.R, g.V0)).sort((a, b) => a - b);
  return { max: e[e.length - 1]!, median: e[e.length >> 1]! };
}

const REPS = 25;
const ROUNDS = 9;
let sink = 0;
/** Microseconds per solve of one impact, over REPS solves in a row. */
function timeOne(solve: Solver, s: CushionState): number {
  const t = performance.now();
  for (let r = 0; r < REPS; r++) sink += solve(s, PAPER).vx;
  return ((performance.now() - t) * 1000) / REPS;
}

// Warm-up (JIT), then the rounds.
for (const s of settings) for (let r = 0; r < 20; r++) for (const st of states) sink += s.solve(st, PAPER).vx;
const samples: number[][][] = settings.map(() => states.map(() => []));
for (let round = 0; round < ROUNDS; round++) {
  states.forEach((st, i) => settings.forEach((s, k) => samples[k]![i]!.push(timeOne(s.solve, st))));
}
const median = (a: readonly number[]): number => [...a].sort((x, y) => x - y)[a.length >> 1]!;
const mean = (a: readonly number[]): number => a.reduce((x, y) => x + y, 0) / a.length;
const perImpact = samples.map((bySetting) => bySetting.map(median));
const medians = perImpact.map(median);
const means = perImpact.map(mean);
const anchor = settings.length - 1;

const rows = settings.map((s, i) => {
  const e = errors(s.solve);
  return `| ${s.name} | ${medians[i]!.toFixed(2)} | ${(medians[anchor]! / medians[i]!).toFixed(1)}× | ` +
    `${means[i]!.toFixed(2)} | ${(means[anchor]! / means[i]!).toFixed(1)}× | ${e.max.toExponential(1)} | ${e.median.toExponential(1)} |`;
});
console.log(`Cushion impacts: ${grid.length} (incidence 0.5-89.5°, V0 0.05-5 m/s, topspin k -1..2, sidespin k -2..2), paper constants, Node ${process.version}.`);
console.log(`Time per impact: median of ${ROUNDS} rounds of ${REPS} solves in a row. Error: |component - reference| / V0 (spins × R).\n`);
console.log('| setting | median µs per impact | speed vs anchors (medians) | mean µs per impact | speed vs anchors (means) | max error | median error |');
console.log('|---|---|---|---|---|---|---|');
for (const r of rows) console.log(r);
if (sink === 42) console.log('');
