// Random shots on each table, seeded: the same scenes in every benchmark that compares whole shots
// (bench:sim's side-by-side column). Balls anywhere on the table, none overlapping; the cue ball
// b0 struck at 0.5-5 m/s in any direction with tip offsets within ±0.3 R.
import type { TableName } from '../physics/index.ts';
import { generator, randomBalls, shot } from './build.ts';
import type { CorpusCase } from './corpus.ts';

/** Balls on the table in a random shot: up to a rack's worth of each game. */
const MAX_BALLS: Readonly<Record<TableName, number>> = { 'pool-9ft': 10, 'snooker-12ft': 22, 'carom-match': 3 };

export function randomShots(table: TableName, count: number, seed = 1): CorpusCase[] {
  const next = generator(seed * 7919 + MAX_BALLS[table]);
  const out: CorpusCase[] = [];
  for (let i = 0; i < count; i++) {
    const max = MAX_BALLS[table];
    const n = table === 'carom-match' ? 3 : 2 + Math.floor(next() * (max - 1));
    const balls = randomBalls(table, n, next);
    const s = shot('b0', next() * 2 * Math.PI, 0.5 + 4.5 * next(), 0.6 * next() - 0.3, 0.6 * next() - 0.3);
    out.push({ name: `random ${table} shot ${i + 1}`, tags: ['random'], scene: { table, balls }, shot: s });
  }
  return out;
}
