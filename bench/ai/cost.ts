// Cost: decision time p50/p99 and simulations per decision for each level, from every computer
// decision the other tables made, with the simulation's own cost per shot in the same run as the
// yardstick (a decision's time is mostly simulations).
import { simulate } from '../../shared/physics/index.ts';
import { newGame, sceneOf } from '../../shared/rules/index.ts';
import type { Timing } from './play.ts';

function quantile(xs: readonly number[], q: number): number {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.min(s.length - 1, Math.floor(q * s.length))]!;
}

/** Median ms of one simulated pool shot of medium speed (a yardstick measured in this run). */
function simulateMs(): number {
  const g = newGame('nineball', ['a', 'b'], { seed: 1 });
  const scene = { ...sceneOf(g), balls: sceneOf(g).balls.map((b) => (b.id === 'cue' ? { ...b, x: 0.2, y: 0.3 } : b)) };
  const ms: number[] = [];
  for (let i = 0; i < 200; i++) {
    const t0 = performance.now();
    simulate(scene, { ball: 'cue', heading: 2 + i * 0.01, speed: 2, side: 0, top: 0 });
    ms.push(performance.now() - t0);
  }
  return quantile(ms, 0.5);
}

export function costTable(timings: readonly Timing[]): void {
  console.log('\n## Cost: decision time and simulations per decision (every decision above; shared 2-core machine)\n');
  console.log(`simulate(): ${simulateMs().toFixed(3)} ms for a medium pool shot (median, this run)\n`);
  console.log('| level | decisions | p50 ms | p99 ms | max ms | simulations p50 | simulations p99 |');
  console.log('|---|---|---|---|---|---|---|');
  for (const level of [1, 2, 3, 4, 5]) {
    const t = timings.filter((x) => x.level === level);
    if (t.length === 0) continue;
    const ms = t.map((x) => x.ms);
    const sims = t.map((x) => x.simulations);
    console.log(`| ${level} | ${t.length} | ${quantile(ms, 0.5).toFixed(0)} | ${quantile(ms, 0.99).toFixed(0)} | ${Math.max(...ms).toFixed(0)} | ${quantile(sims, 0.5)} | ${quantile(sims, 0.99)} |`);
  }
}
