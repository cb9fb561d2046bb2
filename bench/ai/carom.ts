// Three-cushion strength and cost of the computer: points per inning per level (innings from the
// opening position and the positions the level's own play reaches), each level against the level
// below and against the bots' "sound" strategy (short races with an innings cap), and decision time
// and simulations per decision. Run by bench/ai.ts:
//   npm run bench:ai -- --only carom --innings 200 --games 50 --levels 1,2,3,4,5
import { chooseShot as botShot } from '../../bots/strategy.ts';
import { simulate } from '../../shared/physics/index.ts';
import { newGame, playShot, type Game, type Shot, type ThreeCushionGame } from '../../shared/rules/index.ts';
import { chooseShot, type Level } from '../../shared/ai/index.ts';
import { Random } from '../../shared/ai/random.ts';
import { deadline } from './options.ts';

export interface CaromTiming {
  readonly level: number;
  readonly ms: number;
  readonly simulations: number;
}

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

type Player = Level | 'sound';

function decide(g: Game, who: Player, seed: number, timings: CaromTiming[]): Shot {
  if (who === 'sound') return botShot(g, 'sound', simulate);
  const stats = { simulations: 0, candidates: 0 };
  const t0 = performance.now();
  const d = chooseShot(g, { level: who, seed }, stats);
  timings.push({ level: who, ms: performance.now() - t0, simulations: stats.simulations });
  if (!('shot' in d)) throw new Error('three-cushion has no choices');
  return d.shot;
}

/** Points per inning of a level playing both sides from the opening position on. */
export function pointsPerInning(level: Level, innings: number, timings: CaromTiming[], over: () => boolean = () => false): { innings: number; points: number } {
  let g = newGame('threecushion', ['a', 'b'], { raceTo: 100000 });
  let points = 0;
  let played = 0;
  for (let n = 0; played < innings && !over(); n++) {
    const before = g.turn;
    g = playShot(g, decide(g, level, 7919 * n + level, timings)).game;
    if (g.turn === before) points++;
    else played++;
  }
  return { innings: played, points };
}

/** Points per inning from seeded random layouts: each inning starts from a fresh layout. */
export function pointsFromLayouts(level: Level, innings: number, timings: CaromTiming[], over: () => boolean = () => false): { innings: number; points: number } {
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
      g = playShot(g, decide(g, level, 31 * i + n, timings)).game;
      if (g.turn !== before) break;
      points++;
    }
  }
  return { innings: played, points };
}

/** Wins of `a` against `b` (and draws) over `games` races, the break alternating. */
export function match(a: Player, b: Player, o: CaromBenchOptions, timings: CaromTiming[], over: () => boolean = () => false): { wins: number; draws: number; games: number } {
  let wins = 0;
  let draws = 0;
  let played = 0;
  for (let i = 0; i < o.games && !over(); i++, played++) {
    const players = i % 2 === 0 ? ['A', 'B'] : ['B', 'A'];
    let g = newGame('threecushion', players, { raceTo: o.raceTo, seed: i });
    for (let n = 0; g.winner === null && Math.max(...Object.values((g as ThreeCushionGame).innings)) <= o.inningsCap; n++) {
      g = playShot(g, decide(g, g.turn === 'A' ? a : b, 1000003 * i + n, timings)).game;
    }
    if (g.winner === 'A') wins++;
    else if (g.winner === null) draws++;
  }
  return { wins, draws, games: played };
}

function quantile(xs: readonly number[], q: number): number {
  const s = [...xs].sort((x, y) => x - y);
  return s.length === 0 ? NaN : s[Math.min(s.length - 1, Math.floor(q * s.length))]!;
}

/** Runs every table and prints it as markdown; returns the timings for a shared cost table. */
export function caromTables(o: CaromBenchOptions, timings: CaromTiming[] = []): CaromTiming[] {
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
  console.log('\n## Three-cushion: decision cost (every decision above; shared 2-core machine)\n');
  console.log('| level | decisions | p50 ms | p99 ms | simulations p50 | simulations p99 |');
  console.log('|---|---|---|---|---|---|');
  for (const level of levels) {
    const t = timings.filter((x) => x.level === level);
    if (t.length === 0) continue;
    const ms = t.map((x) => x.ms);
    const sims = t.map((x) => x.simulations);
    console.log(`| ${level} | ${t.length} | ${quantile(ms, 0.5).toFixed(0)} | ${quantile(ms, 0.99).toFixed(0)} | ${quantile(sims, 0.5)} | ${quantile(sims, 0.99)} |`);
  }
  return timings;
}
