// npm run bench:cushion — speed against error of the cushion kernel at each tolerance and of
// the anchors' scheme (bench/cushion-anchor.ts), timed side by side in one run on the same
// 528 impacts (tests/support/cushion-cases.ts, benchGrid), paper constants. Errors are against
// the converged reference (tests/support/cushion-reference.ts), as a fraction of V0, over every
// component (spins times R). Prints a markdown table.
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

let sink = 0;
/** Microseconds per impact for one pass over the grid, repeated `reps` times. */
function pass(solve: Solver, reps: number): number {
  const t = performance.now();
  for (let r = 0; r < reps; r++) {
    for (let i = 0; i < states.length; i++) sink += solve(states[i]!, PAPER).vx;
  }
  return ((performance.now() - t) * 1000) / (reps * states.length);
}

// Warm-up (JIT), then rounds that time every setting in turn, so that all settings see the
// same machine state; the median over rounds is reported.
for (const s of settings) pass(s.solve, 20);
const ROUNDS = 15;
const samples: number[][] = settings.map(() => []);
for (let r = 0; r < ROUNDS; r++) {
  settings.forEach((s, i) => samples[i]!.push(pass(s.solve, 4)));
}
const median = (a: number[]): number => [...a].sort((x, y) => x - y)[a.length >> 1]!;
const times = samples.map(median);
const anchorTime = times[times.length - 1]!;

const rows = settings.map((s, i) => {
  const e = errors(s.solve);
  return `| ${s.name} | ${times[i]!.toFixed(2)} | ${(anchorTime / times[i]!).toFixed(1)}× | ${e.max.toExponential(1)} | ${e.median.toExponential(1)} |`;
});
console.log(`Cushion impacts: ${grid.length} (incidence 0.5-89.5°, V0 0.05-5 m/s, topspin k -1..2, sidespin k -2..2), paper constants, Node ${process.version}.`);
console.log(`Time: median of ${ROUNDS} rounds of the mean per impact. Error: |component - reference| / V0 (spins × R).\n`);
console.log('| setting | µs per impact | speed vs anchors | max error | median error |');
console.log('|---|---|---|---|---|');
for (const r of rows) console.log(r);
if (sink === 42) console.log('');
