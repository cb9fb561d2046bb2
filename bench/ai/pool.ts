// Nine-ball and eight-ball: each level against the level below and against the bots' "sound"
// strategy (breaks alternate: the first of each pair of games is broken by the stronger side), and
// the share of racks run out from ball in hand after a break.
import type { Level } from '../../shared/ai/index.ts';
import { chooseShot } from '../../shared/ai/index.ts';
import { newGame, playShot, type Game, type GameKind } from '../../shared/rules/index.ts';
import { deadline, type BenchOptions } from './options.ts';
import { margin, pct, playGame, step, type Player, type Timing } from './play.ts';

/** Win share of `a` over `n` games against `b` (alternating who breaks); unfinished games count half. */
export function match(kind: GameKind, a: Player, b: Player, n: number, seed0: number, budget: number, maxShots: number, timings: Timing[]): { wins: number; played: number } {
  const over = deadline(budget);
  let wins = 0;
  let played = 0;
  for (let i = 0; i < n && !over(); i++) {
    const seed = seed0 + i;
    const w = i % 2 === 0 ? playGame(kind, a, b, seed, maxShots, timings) : playGame(kind, b, a, seed, maxShots, timings);
    const aWon = w === -1 ? 0.5 : (i % 2 === 0) === (w === 0) ? 1 : 0;
    wins += aWon;
    played++;
  }
  return { wins, played };
}

export function strengthTable(kind: GameKind, o: BenchOptions, timings: Timing[], maxShots = 400): void {
  console.log(`\n## ${kind}: win rates (${o.games} games a pairing asked; breaks alternate)\n`);
  console.log('| level | vs level below | games | ±95% | vs "sound" bot | games | ±95% |');
  console.log('|---|---|---|---|---|---|---|');
  for (const l of o.levels) {
    const level = l as Level;
    let below = '-';
    let belowN = 0;
    let belowM = '';
    if (l > 1) {
      const r = match(kind, level, (l - 1) as Level, o.games, 100 * l, o.budget, maxShots, timings);
      below = r.played ? pct(r.wins / r.played) : '-';
      belowN = r.played;
      belowM = r.played ? pct(margin(r.wins / r.played, r.played)) : '';
    }
    const s = match(kind, level, 'sound', o.games, 7000 + 100 * l, o.budget, maxShots, timings);
    console.log(`| ${l} | ${below} | ${belowN} | ${belowM} | ${s.played ? pct(s.wins / s.played) : '-'} | ${s.played} | ${s.played ? pct(margin(s.wins / s.played, s.played)) : ''} |`);
  }
}

/** The rack after a break by level 5, with the balls where the break left them and ball in hand for 'a'. */
export function afterBreak(kind: GameKind, seed: number): Game | null {
  let g = newGame(kind, ['a', 'b'], { seed });
  const d = chooseShot(g, { level: 5, seed });
  if (!('shot' in d)) return null;
  g = playShot(g, d.shot, d.cueBall).game;
  if (g.winner !== null) return null;
  const base = { ...g, turn: 'a', ballInHand: 'anywhere' as const, choices: [], verdict: null };
  return kind === 'nineball' ? ({ ...base, phase: 'play' } as Game) : ({ ...base, phase: 'play' } as Game);
}

/** Whether level `l` clears the table from `start` without giving up the turn. */
export function runsOut(start: Game, level: Level, seed: number, timings: Timing[]): boolean {
  let g = start;
  for (let i = 0; i < 40 && g.winner === null && g.turn === 'a'; i++) g = step(g, level, seed * 100 + i, timings);
  return g.winner === 'a';
}

export function runOutTable(kind: GameKind, o: BenchOptions, timings: Timing[]): void {
  console.log(`\n## ${kind}: racks run out from ball in hand after a break (${o.racks} seeded racks asked)\n`);
  console.log('| level | run out | racks | ±95% |');
  console.log('|---|---|---|---|');
  const starts: Game[] = [];
  for (let s = 1; starts.length < o.racks && s < 10 * o.racks + 10; s++) {
    const g = afterBreak(kind, s);
    if (g) starts.push(g);
  }
  for (const l of o.levels) {
    const over = deadline(o.budget);
    let n = 0;
    let outs = 0;
    for (const g of starts) {
      if (over()) break;
      n++;
      if (runsOut(g, l as Level, n, timings)) outs++;
    }
    console.log(`| ${l} | ${n ? pct(outs / n) : '-'} | ${n} | ${n ? pct(margin(outs / n, n)) : ''} |`);
  }
}
