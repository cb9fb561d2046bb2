// Snooker: win rates as for pool, and the break each level makes from the balls as a standard
// break-off (played by level 5) leaves them, the computer to play.
import { chooseShot, type Level } from '../../shared/ai/index.ts';
import { newGame, playShot, type Game } from '../../shared/rules/index.ts';
import { deadline, type BenchOptions } from './options.ts';
import { step, type Timing } from './play.ts';
import { strengthTable } from './pool.ts';

export function afterBreakOff(seed: number): Game {
  let g = newGame('snooker', ['b', 'a'], { seed });
  const d = chooseShot(g, { level: 5, seed });
  if ('shot' in d) g = playShot(g, d.shot, d.cueBall).game;
  return { ...g, turn: 'a', choices: [], freeBall: false, offender: null, verdict: null } as Game;
}

/** Points 'a' scores before the turn passes. */
export function breakFrom(start: Game, level: Level, seed: number, timings: Timing[]): number {
  let g = start;
  const before = g.scores.a ?? 0;
  for (let i = 0; i < 60 && g.winner === null && g.turn === 'a'; i++) {
    const next = step(g, level, seed * 100 + i, timings);
    if (next.turn !== 'a' || next.verdict?.foul) return (g.scores.a ?? 0) - before;
    g = next;
  }
  return (g.scores.a ?? 0) - before;
}

/** The frame played on by the level against itself: every visit's break (g.break as it grows). */
export function frameBreaks(start: Game, level: Level, seed: number, timings: Timing[], maxShots = 160): number[] {
  let g = start;
  const visits: number[] = [];
  let current = 0;
  for (let i = 0; i < maxShots && g.winner === null; i++) {
    const next = step(g, level, seed * 1000 + i, timings);
    if (next.turn === g.turn && !next.verdict?.foul) current = next.kind === 'snooker' ? next.break : 0;
    else {
      visits.push(current);
      current = 0;
    }
    g = next;
  }
  if (current > 0) visits.push(current);
  return visits;
}

export function snookerTables(o: BenchOptions, timings: Timing[]): void {
  console.log(`\n## snooker: breaks from a standard break-off (${o.frames} frames asked)\n`);
  console.log('| level | mean break | highest | frames |');
  console.log('|---|---|---|---|');
  const starts: Game[] = [];
  for (let s = 1; s <= o.frames; s++) starts.push(afterBreakOff(s));
  for (const l of o.levels) {
    const over = deadline(o.budget);
    const breaks: number[] = [];
    for (const g of starts) {
      if (over()) break;
      breaks.push(breakFrom(g, l as Level, breaks.length + 1, timings));
    }
    const mean = breaks.length ? breaks.reduce((a, b) => a + b, 0) / breaks.length : 0;
    console.log(`| ${l} | ${breaks.length ? mean.toFixed(1) : '-'} | ${breaks.length ? Math.max(...breaks) : '-'} | ${breaks.length} |`);
  }
  console.log(`\n## snooker: the frame played on from the break-off, the level against itself (${o.frames} frames asked)\n`);
  console.log('| level | mean of each frame\'s highest break | highest | mean scoring visit | frames |');
  console.log('|---|---|---|---|---|');
  for (const l of o.levels) {
    const over = deadline(o.budget);
    const highs: number[] = [];
    const scoring: number[] = [];
    for (const g of starts) {
      if (over()) break;
      const v = frameBreaks(g, l as Level, highs.length + 1, timings);
      highs.push(v.length ? Math.max(...v) : 0);
      scoring.push(...v.filter((x) => x > 0));
    }
    const mean = (xs: number[]): string => (xs.length ? (xs.reduce((a, b) => a + b, 0) / xs.length).toFixed(1) : '-');
    console.log(`| ${l} | ${mean(highs)} | ${highs.length ? Math.max(...highs) : '-'} | ${mean(scoring)} | ${highs.length} |`);
  }
  strengthTable('snooker', o, timings, 600);
}
