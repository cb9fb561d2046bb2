// The golden corpus: scenes and shots defined once, used by the determinism tests (whose hashes
// are committed), the benchmarks and the client's debug views. Breaks on each table, banks, spin
// shots, side spin, pockets and jaws, and the hard cases every engine must survive (docs/simulation.md).
import { tableSpec, type Scene, type SceneBall, type Shot, type TableName } from '../physics/index.ts';
import { newGame } from '../rules/index.ts';
import { aim, frozenLine, generator, ghost, onRail, randomBalls, shot, type Point } from './build.ts';

export type CorpusTag = 'break' | 'nineball-break' | 'snooker-break' | 'carom' | 'single' | 'bank' | 'spin' | 'english' | 'pocket' | 'hard' | 'random';

export interface CorpusCase {
  readonly name: string;
  readonly tags: readonly CorpusTag[];
  readonly scene: Scene;
  readonly shot: Shot;
}

const POOL: TableName = 'pool-9ft';
const SNOOKER: TableName = 'snooker-12ft';
const CAROM: TableName = 'carom-match';
const R_POOL = tableSpec(POOL).ballRadius;
const R_SNOOKER = tableSpec(SNOOKER).ballRadius;
const R_CAROM = tableSpec(CAROM).ballRadius;

function racked(kind: 'nineball' | 'eightball' | 'snooker' | 'threecushion', seed: number): SceneBall[] {
  return newGame(kind, ['p1', 'p2'], { seed }).balls.map((b) => ({ id: b.id, x: b.x, y: b.y }));
}

function find(balls: readonly SceneBall[], id: string): SceneBall {
  const b = balls.find((x) => x.id === id);
  if (!b) throw new Error(`corpus: no ball ${id}`);
  return b;
}

function moved(balls: readonly SceneBall[], id: string, to: Point): SceneBall[] {
  return balls.map((b) => (b.id === id ? { id, x: to.x, y: to.y } : b));
}

const cases: CorpusCase[] = [];
function add(name: string, tags: CorpusTag[], table: TableName, balls: SceneBall[], s: Shot): void {
  cases.push({ name, tags, scene: { table, balls }, shot: s });
}

// Breaks. Nine-ball: the cue ball from the head string at the apex (1) ball.
[
  [1, 0, 7, 0.1],
  [2, 0.1, 8, 0],
  [3, -0.2, 9, -0.1],
  [4, 0.25, 11, 0.05],
].forEach(([seed, y, speed, top]) => {
  const balls = moved(racked('nineball', seed!), 'cue', { x: -0.9525, y: y! });
  add(`nineball break ${speed} m/s from y=${y}`, ['break', 'nineball-break'], POOL, balls, shot('cue', aim(find(balls, 'cue'), find(balls, '1')), speed!, 0, top));
});
[
  [1, 8],
  [2, 10],
  [3, 12],
].forEach(([seed, speed]) => {
  const balls = moved(racked('eightball', seed!), 'cue', { x: -0.9525, y: 0.15 });
  const apex = balls.reduce((a, b) => (b.id !== 'cue' && b.x < a.x ? b : a), find(balls, '1'));
  add(`eightball break ${speed} m/s`, ['break'], POOL, balls, shot('cue', aim(find(balls, 'cue'), apex), speed!, 0, 0));
});
// Snooker: from the D, a thin hit on the last red of the back row, the usual safe break.
[
  [5, 0.2],
  [7, 0],
  [10, -0.1],
].forEach(([speed, side]) => {
  const balls = moved(racked('snooker', 1), 'cue', { x: -1.0475, y: -0.146 });
  const back = balls.filter((b) => b.id.startsWith('red')).reduce((a, b) => (b.x > a.x || (b.x === a.x && b.y < a.y) ? b : a));
  const target = { x: back.x, y: back.y - 1.9 * R_SNOOKER };
  add(`snooker break ${speed} m/s`, ['break', 'snooker-break'], SNOOKER, balls, shot('cue', aim(find(balls, 'cue'), target), speed!, side!, 0));
});
// Carom: the opening shot, white onto the red, with running side.
[
  [2, 0.3, 0.2],
  [3, -0.3, 0.1],
  [4, 0.4, 0],
  [6, 0.2, 0.3],
].forEach(([speed, side, top]) => {
  const balls = racked('threecushion', 1);
  const red = find(balls, 'red');
  add(`carom opening ${speed} m/s side ${side}`, ['carom'], CAROM, balls, shot('white', aim(find(balls, 'white'), { x: red.x, y: red.y + 0.8 * R_CAROM }), speed!, side!, top!));
});
// Carom: three-ball positions across the table.
[
  [11, 3],
  [12, 4],
  [13, 5],
].forEach(([seed, speed]) => {
  const next = generator(seed!);
  const balls = randomBalls(CAROM, 3, next).map((b, i) => ({ ...b, id: ['white', 'yellow', 'red'][i]! }));
  add(`carom position ${seed}`, ['carom'], CAROM, balls, shot('white', aim(balls[0]!, balls[2]!) + 0.05, speed!, 0.3 * (2 * next() - 1), 0.3 * (2 * next() - 1)));
});

// Banks and single balls.
add('pool head-on into the long rail', ['bank', 'single'], POOL, [{ id: 'cue', x: 0.3, y: 0 }], shot('cue', Math.PI / 2, 2));
add('pool 30° bank with right english', ['bank', 'single', 'spin'], POOL, [{ id: 'cue', x: -0.8, y: -0.3 }], shot('cue', Math.PI / 6, 3, 0.4, 0));
add('snooker up and down the table', ['bank', 'single'], SNOOKER, [{ id: 'cue', x: -1.2, y: 0.1 }], shot('cue', 0.02, 4, 0, 0.2));
add('carom long diagonal with side', ['bank', 'single', 'carom'], CAROM, [{ id: 'white', x: -1.2, y: -0.5 }], shot('white', 0.45, 4, 0.3, 0));
add('grazing incidence on a rail (0.3°)', ['bank', 'single', 'hard'], POOL, [{ id: 'cue', x: -0.9, y: 0.55 }], shot('cue', 0.005235987755982988, 3));
add('very slow into a cushion (0.05 m/s)', ['bank', 'single', 'hard'], POOL, [{ id: 'cue', x: 0.2, y: 0.6044 }], shot('cue', Math.PI / 2, 0.05));
add('frozen to a rail, struck along it', ['bank', 'single', 'hard'], POOL, [{ id: 'cue', ...onRail(POOL, 'top', -0.9) }], shot('cue', 0, 2, 0, 0.2));
add('frozen to a rail, struck into it', ['bank', 'single', 'hard'], POOL, [{ id: 'cue', ...onRail(POOL, 'bottom', 0.4) }], shot('cue', -Math.PI / 3, 1.5));
add('carom straight into a corner (two cushions at once)', ['bank', 'single', 'hard'], CAROM, [{ id: 'white', x: 0.5, y: -0.2 }], shot('white', aim({ x: 0.5, y: -0.2 }, { x: 1.38925, y: 0.67925 }), 3));
add('pool hard bank beyond the rigid limit (6 m/s)', ['bank', 'single', 'hard'], POOL, [{ id: 'cue', x: 0, y: 0 }], shot('cue', 1.2, 6, -0.2, 0.3));

// Spin shots on a pool object ball.
const cueAt = { x: -0.5, y: 0 };
const objAt = { x: 0.1, y: 0 };
add('draw shot', ['spin'], POOL, [{ id: 'cue', ...cueAt }, { id: '1', ...objAt }], shot('cue', 0, 3, 0, -0.4));
add('follow shot (equal accelerations after)', ['spin', 'hard'], POOL, [{ id: 'cue', ...cueAt }, { id: '1', ...objAt }], shot('cue', 0, 3, 0, 0.4));
add('stun shot', ['spin'], POOL, [{ id: 'cue', x: 0.0, y: 0 }, { id: '1', x: 0.2, y: 0 }], shot('cue', 0, 2, 0, 0));
{
  const target = { x: 1.27, y: 0.635 };
  const g = ghost(objAt, target, R_POOL);
  add('cut toward a corner with right english (throw)', ['spin', 'pocket'], POOL, [{ id: 'cue', ...cueAt }, { id: '1', ...objAt }], shot('cue', aim(cueAt, g), 2, 0.4, 0));
  add('cut toward a corner, slow stun (most throw)', ['spin', 'pocket'], POOL, [{ id: 'cue', ...cueAt }, { id: '1', ...objAt }], shot('cue', aim(cueAt, g), 0.5, 0, 0));
}
add('pure sidespin off a rail', ['spin', 'single', 'bank'], POOL, [{ id: 'cue', x: 0, y: -0.3 }], shot('cue', Math.PI / 2, 1.5, 0.45, 0));
add('snooker screw back', ['spin'], SNOOKER, [{ id: 'cue', x: -0.6, y: 0.2 }, { id: 'black', x: 0.2, y: 0.2 }], shot('cue', 0, 4, 0, -0.45));
add('spin in place (very slow with side)', ['spin', 'single', 'hard'], POOL, [{ id: 'cue', x: 0, y: 0 }], shot('cue', 1, 0.01, 0.4, 0));

// Side spin (english), each with its mirror image: right english (side > 0) off a rail hit square
// comes back to the shooter's right, throws a full-hit object ball to the left, and is running
// english on a ball angling to the right into a rail (a wider, faster rebound).
for (const [name, side] of [['right', 0.4], ['no', 0], ['left', -0.4]] as const) {
  add(`${name} english straight into a rail`, ['english', 'spin', 'single', 'bank'], POOL, [{ id: 'cue', x: 0.6, y: 0 }], shot('cue', 0, 1.5, side, 0));
  add(`${name} english full hit on an object ball`, ['english', 'spin'], POOL, [{ id: 'cue', x: -0.5, y: 0 }, { id: '1', x: 0.1, y: 0 }], shot('cue', 0, 1, side, 0));
  add(`${name} english angling right into a rail`, ['english', 'spin', 'single', 'bank'], POOL, [{ id: 'cue', x: -0.9, y: 0 }], shot('cue', Math.PI / 4, 1.5, side, 0));
}

// Pockets and jaws.
add('pot into the top-right corner', ['pocket', 'single'], POOL, [{ id: 'cue', x: 0.6, y: -0.3 }], shot('cue', aim({ x: 0.6, y: -0.3 }, { x: 1.3, y: -0.665 }), 2));
add('pot into a middle pocket', ['pocket', 'single'], POOL, [{ id: 'cue', x: 0, y: 0 }], shot('cue', Math.PI / 2, 1.5));
add('rattle in a corner jaw', ['pocket', 'single', 'hard'], POOL, [{ id: 'cue', x: 0.6, y: 0.4 }], shot('cue', aim({ x: 0.6, y: 0.4 }, { x: 1.2, y: 0.65 }), 2.5));
add('middle pocket jaw at an angle', ['pocket', 'single', 'hard'], POOL, [{ id: 'cue', x: -0.5, y: 0.2 }], shot('cue', aim({ x: -0.5, y: 0.2 }, { x: 0.06, y: 0.62 }), 2));
add('scratch: cue ball into a corner after the object ball', ['pocket'], POOL, [{ id: 'cue', x: 0.5, y: 0.1 }, { id: '8', x: 0.8, y: 0.25 }], shot('cue', aim({ x: 0.5, y: 0.1 }, { x: 0.8, y: 0.25 }), 3, 0, 0.4));
{
  const black = { x: 1.2, y: 0.5 };
  const g = ghost(black, { x: 1.8, y: 0.9 }, R_SNOOKER);
  const cue = { x: 0.6, y: 0.3 };
  add('snooker black into the corner', ['pocket'], SNOOKER, [{ id: 'cue', ...cue }, { id: 'black', ...black }], shot('cue', aim(cue, g), 2.5));
}
add('snooker corner jaw rattle', ['pocket', 'single', 'hard'], SNOOKER, [{ id: 'cue', x: 1.2, y: 0.3 }], shot('cue', aim({ x: 1.2, y: 0.3 }, { x: 1.76, y: 0.83 }), 3));
add('snooker middle pocket', ['pocket', 'single'], SNOOKER, [{ id: 'cue', x: 0.02, y: -0.3 }], shot('cue', -Math.PI / 2, 2));

// Hard cases (docs/simulation.md, "Hard cases and how they are met").
add('line of three frozen balls struck straight', ['hard'], POOL, [{ id: 'cue', x: -0.6, y: 0 }, ...frozenLine(['1', '2', '3'], { x: 0, y: 0 }, 1, 0, R_POOL)], shot('cue', 0, 3));
add('line of five frozen balls struck straight', ['hard'], POOL, [{ id: 'cue', x: -0.6, y: 0.1 }, ...frozenLine(['1', '2', '3', '4', '5'], { x: 0, y: 0.1 }, 1, 0, R_POOL)], shot('cue', 0, 5, 0, 0.3));
add('cue ball frozen to the object ball', ['hard'], POOL, [{ id: 'cue', x: 0, y: 0 }, { id: '1', x: 2 * R_POOL, y: 0 }], shot('cue', 0.3, 1.5));
add('frozen pair combination', ['hard'], POOL, [{ id: 'cue', x: -0.7, y: -0.2 }, ...frozenLine(['1', '2'], { x: 0.3, y: 0.1 }, 0.6, 0.8, R_POOL)], shot('cue', aim({ x: -0.7, y: -0.2 }, { x: 0.3 - 0.9 * R_POOL, y: 0.1 }), 3));
add('two balls hit at the same instant', ['hard'], POOL, [{ id: 'cue', x: -0.5, y: 0 }, { id: '1', x: 0.2, y: R_POOL }, { id: '2', x: 0.2, y: -R_POOL }], shot('cue', 0, 4));
add('grazing ball-ball contact', ['hard'], POOL, [{ id: 'cue', x: -0.5, y: 0 }, { id: '1', x: 0.3, y: 2 * R_POOL * 0.9999999 }], shot('cue', 0, 2));
add('near miss by a micrometre', ['hard'], POOL, [{ id: 'cue', x: -0.5, y: 0 }, { id: '1', x: 0.3, y: 2 * R_POOL + 1e-6 }], shot('cue', 0, 2));
{
  // The object ball sits where the stunned cue ball stops sliding: t_s = 2v/(7 μ g), x = v t_s - μ g t_s²/2.
  const t = tableSpec(POOL);
  const v = 2;
  const ts = (2 * v) / (7 * t.cloth.muSlide * t.g);
  const x = -0.8 + v * ts - 0.5 * t.cloth.muSlide * t.g * ts * ts + 2 * R_POOL;
  add('state change at the instant of a collision', ['hard'], POOL, [{ id: 'cue', x: -0.8, y: 0 }, { id: '1', x, y: 0 }], shot('cue', 0, v));
}
add('ball frozen to a rail and to another ball', ['hard'], POOL, [{ id: 'cue', x: -0.3, y: 0.2 }, { id: '1', ...onRail(POOL, 'top', 0.2) }, { id: '2', x: 0.2 + 2 * R_POOL, y: onRail(POOL, 'top', 0).y }], shot('cue', aim({ x: -0.3, y: 0.2 }, onRail(POOL, 'top', 0.2)), 2.5));
add('slow nudge into a frozen rack', ['hard'], POOL, moved(racked('nineball', 5), 'cue', { x: 0.635 - 2 * R_POOL - 0.01, y: 0 }), shot('cue', 0, 0.05));
add('snooker hard break beyond the rigid limit', ['hard', 'break'], SNOOKER, moved(racked('snooker', 2), 'cue', { x: -1.0475, y: -0.1 }), shot('cue', 0, 12, 0, 0.2));
add('extreme spin: full draw and side', ['hard', 'spin'], POOL, [{ id: 'cue', x: -0.3, y: -0.3 }, { id: '1', x: 0.4, y: 0.1 }], shot('cue', aim({ x: -0.3, y: -0.3 }, { x: 0.4, y: 0.1 }), 8, 0.35, -0.35));

// Random scenes, seeded.
const TABLES: TableName[] = [POOL, SNOOKER, CAROM];
for (let seed = 1; seed <= 12; seed++) {
  const next = generator(1000 + seed);
  const table = TABLES[seed % 3]!;
  const balls = randomBalls(table, 2 + Math.floor(next() * 9), next);
  const speed = 0.2 + 5 * next();
  add(`random scene ${seed}`, ['random'], table, balls, shot('b0', next() * 2 * Math.PI, speed, 0.6 * next() - 0.3, 0.6 * next() - 0.3));
}

export const CORPUS: readonly CorpusCase[] = cases;

/** The corpus cases with a tag. */
export function corpusCases(tag?: CorpusTag): readonly CorpusCase[] {
  return tag ? CORPUS.filter((c) => c.tags.includes(tag)) : CORPUS;
}
