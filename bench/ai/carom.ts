// Three-cushion strength and cost of the computer: points per inning per level (innings from the
// opening position and the positions the level's own play reaches), each level against the level
// below and against the bots' "sound" strategy (short races with an innings cap); its decisions'
// times go to the shared cost table. Run by bench/ai.ts:
//   npm run bench:ai -- --only carom,cost --innings 200 --games 50 --levels 1,2,3,4,5
import { newGame, type Game, type ThreeCushionGame } from '../../shared/rules/index.ts';
import type { Level } from '../../shared/ai/index.ts';
import { Random } from '../../shared/ai/random.ts';
import { deadline } from './options.ts';
import { step, type Player, type Timing } from './play.ts';

export interface CaromBenchOptions {
  readonly innings: number;
  readonly games: number;
  readonly levels: readonly number[];
  readonly raceTo: number;
  /** Innings per player after which a game is a draw. */
  readonly inningsCap: number;
  /** Seconds one table (a level's row) may take before it stops and says how many it played. */
  readonly budget: number;
}

/** Points per inning of a level playing both sides from the opening position on. */
export function pointsPerInning(level: Level, innings: number, timings: Timing[], over: () => boolean = () => false): { innings: number; points: number } {
  let g = newGame('threecushion', ['a', 'b'], { raceTo: 100000 });
  let points = 0;
  let played = 0;
  for (let n = 0; played < innings && !over(); n++) {
    const before = g.turn;
    g = step(g, level, 7919 * n + level, timings);
    if (g.turn === before) points++;
    else played++;
  }
  return { innings: played, points };
}

/** Points per inning from seeded random layouts: each inning starts from a fresh layout. */
export function pointsFromLayouts(level: Level, innings: number, timings: Timing[], over: () => boolean = () => false): { innings: number; points: number } {
  const random = new Random(424242);
  let points = 0;
  let played = 0;
  for (let i = 0; i < innings && !over(); i++, played++) {
    let g: Game = { ...newGame('threecushion', ['a', 'b'], { raceTo: 100000 }), shots: 1 };
    const balls: { id: string; x: number; y: number }[] = [];
    for (const id of ['white', 'yellow', 'red']) {
      for (;;) {
        const x = (random.uniform() - 0.5) * 2.6;
        const y = (random.uniform() - 0.5) * 1.2;
        if (balls.every((b) => (b.x - x) * (b.x - x) + (b.y - y) * (b.y - y) > 0.01)) {
          balls.push({ id, x, y });
          break;
        }
      }
    }
    g = { ...g, balls };
    for (let n = 0; ; n++) {
      const before = g.turn;
      g = step(g, level, 31 * i + n, timings);
      if (g.turn !== before) break;
      points++;
    }
  }
  return { innings: played, points };
}

/** Wins of `a` against `b` (and draws) over `games` races, the break alternating. */
export function match(a: Player, b: Player, o: CaromBenchOptions, timings: Timing[], over: () => boolean = () => false): { wins: number; draws: number; games: number } {
  let wins = 0;
  let draws = 0;
  let played = 0;
  for (let i = 0; i < o.games && !over(); i++, played++) {
    const players = i % 2 === 0 ? ['A', 'B'] : ['B', 'A'];
    let g = newGame('threecushion', players, { raceTo: o.raceTo, seed: i });
    for (let n = 0; g.winner === null && Math.max(...Object.values((g as ThreeCushionGame).innings)) <= o.inningsCap; n++) {
      g = step(g, g.turn === 'A' ? a : b, 1000003 * i + n, timings);
    }
    if (g.winner === 'A') wins++;
    else if (g.winner === null) draws++;
  }
  return { wins, draws, games: played };
}

/** Runs every table and prints it as markdown; the decisions' times go to `timings`. */
export function caromTables(o: CaromBenchOptions, timings: Timing[]): void {
  const levels = o.levels.filter((l): l is Level => l >= 1 && l <= 5);
  console.log('\n## Three-cushion: points per inning (self-play from the opening position, positions reached in play)\n');
  console.log('| level | innings | points | points per inning |');
  console.log('|---|---|---|---|');
  for (const level of levels) {
    const r = pointsPerInning(level, o.innings, timings, deadline(o.budget));
    console.log(`| ${level} | ${r.innings} | ${r.points} | ${(r.points / r.innings).toFixed(2)} |`);
  }
  console.log('\n## Three-cushion: points per inning from seeded random layouts (one inning each)\n');
  console.log('| level | innings | points | points per inning |');
  console.log('|---|---|---|---|');
  for (const level of levels) {
    const r = pointsFromLayouts(level, o.innings, timings, deadline(o.budget));
    console.log(`| ${level} | ${r.innings} | ${r.points} | ${(r.points / r.innings).toFixed(2)} |`);
  }
  if (o.games > 0) {
    console.log(`\n## Three-cushion: win rates (races to ${o.raceTo}, a draw after ${o.inningsCap} innings each, break alternating)\n`);
    console.log('| level | opponent | games | wins | draws | win rate |');
    console.log('|---|---|---|---|---|---|');
    for (const level of levels) {
      const opponents: Player[] = level > 1 ? [(level - 1) as Level, 'sound'] : ['sound'];
      for (const opp of opponents) {
        const r = match(level, opp, o, timings, deadline(o.budget));
        console.log(`| ${level} | ${opp === 'sound' ? 'bots "sound"' : `level ${opp}`} | ${r.games} | ${r.wins} | ${r.draws} | ${((100 * r.wins) / r.games).toFixed(0)}% |`);
      }
    }
  }
}
