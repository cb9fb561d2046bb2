// Practice: one player, any balls placed anywhere on the bed (validated), shots that only move the
// balls, undo of the last steps, and the list of shots to replay through the simulation.
import type { TableName, TableSpec } from '../physics/tables.ts';
import { assertPlayerOnTurn, describeList, putInHand, specOfGame } from './common.ts';
import { RuleError } from './errors.ts';
import type { ShotFacts } from './outcome.ts';
import { placementProblem, preferredSpot } from './placement.ts';
import {
  CAROM_BALLS,
  caromSetup,
  eightBallRack,
  nineBallRack,
  POOL_CUE,
  POOL_OBJECT_BALLS,
  SNOOKER_COLOURS,
  SNOOKER_REDS,
  snookerSetup,
} from './racks.ts';
import type { Ball, PracticeGame, PracticeLayout, PlayerId, Shot, StrikeParams, Verdict } from './types.ts';

/** Undo steps kept; older ones are dropped. */
export const PRACTICE_HISTORY_LIMIT = 1000;

const LAYOUT_TABLE: Readonly<Record<Exclude<PracticeLayout, 'empty'>, TableName>> = {
  nineball: 'pool-9ft',
  eightball: 'pool-9ft',
  snooker: 'snooker-12ft',
  threecushion: 'carom-match',
};

export function practiceTableAndLayout(
  table: TableName | undefined,
  layout: PracticeLayout | undefined,
): { table: TableName; layout: PracticeLayout } {
  if (layout !== undefined && layout !== 'empty' && !(layout in LAYOUT_TABLE)) {
    throw new RuleError('bad-options', `unknown practice layout "${String(layout)}"`);
  }
  const t: TableName = table ?? (layout && layout !== 'empty' ? LAYOUT_TABLE[layout] : 'pool-9ft');
  const l: PracticeLayout =
    layout ?? (t === 'snooker-12ft' ? 'snooker' : t === 'carom-match' ? 'threecushion' : 'eightball');
  if (l !== 'empty' && LAYOUT_TABLE[l] !== t) {
    throw new RuleError('bad-options', `the ${l} layout is set on the ${LAYOUT_TABLE[l]} table, not ${t}`);
  }
  return { table: t, layout: l };
}

export function practiceLayout(spec: TableSpec, layout: PracticeLayout, rng: number): { balls: Ball[]; rng: number } {
  switch (layout) {
    case 'nineball':
      return nineBallRack(spec, rng);
    case 'eightball':
      return eightBallRack(spec, rng);
    case 'snooker':
      return { balls: snookerSetup(spec), rng };
    case 'threecushion':
      return { balls: caromSetup(spec), rng };
    case 'empty':
      return {
        balls: [{ id: spec.name === 'carom-match' ? 'white' : POOL_CUE, ...preferredSpot(spec, 'anywhere') }],
        rng,
      };
  }
}

/** Ball ids a table's set has. */
export function ballSet(table: TableName): readonly string[] {
  if (table === 'snooker-12ft') return [POOL_CUE, ...SNOOKER_REDS, ...SNOOKER_COLOURS];
  if (table === 'carom-match') return CAROM_BALLS;
  return [POOL_CUE, ...POOL_OBJECT_BALLS];
}

/** The balls a practice shot may strike: the cue ball, or either carom cue ball. */
export function practiceCueBalls(g: PracticeGame): string[] {
  return g.table === 'carom-match' ? ['white', 'yellow'] : [POOL_CUE];
}

function pushStep(g: PracticeGame, shot: Shot | null): void {
  g.history.push({ balls: g.balls.map((b) => ({ ...b })), ballInHand: g.ballInHand, score: g.scores[g.turn] ?? 0, shot });
  if (g.history.length > PRACTICE_HISTORY_LIMIT) g.history.splice(0, g.history.length - PRACTICE_HISTORY_LIMIT);
}

export function judgePractice(g: PracticeGame, shot: Shot, f: ShotFacts, v: Verdict): void {
  const spec = specOfGame(g);
  pushStep(g, shot);
  g.balls = f.remaining;
  g.shots += 1;
  g.ballInHand = false;
  const cueBalls = practiceCueBalls(g);
  const objects = f.pots.filter((p) => !cueBalls.includes(p.id)).map((p) => p.id);
  v.potted = objects;
  g.scores[shot.player] = (g.scores[shot.player] ?? 0) + objects.length;
  v.points[shot.player] = objects.length;
  v.continues = true;
  v.next = shot.player;
  v.message = `potted ${describeList(objects)}`;
  if (f.pots.some((p) => p.id === shot.ball)) {
    addScratch(v);
    if (g.table !== 'carom-match') {
      g.balls = putInHand(spec, g.balls, shot.ball, 'anywhere');
      g.ballInHand = 'anywhere';
      v.message += '; the cue ball went down: it is in hand anywhere';
    }
  }
}

function addScratch(v: Verdict): void {
  v.foul = true;
  v.reason = 'scratch';
  v.fouls = ['scratch'];
}

/** Validate a whole set of balls for `table`: known ids, no duplicates, on the bed, no overlaps. */
export function checkLayout(spec: TableSpec, table: TableName, balls: readonly Ball[]): void {
  if (!Array.isArray(balls)) throw new RuleError('bad-placement', 'balls must be an array of { id, x, y }');
  const allowed = ballSet(table);
  const seen: Ball[] = [];
  for (const b of balls) {
    if (!b || typeof b.id !== 'string' || !allowed.includes(b.id)) {
      throw new RuleError('bad-placement', `"${String(b?.id)}" is not a ball of the ${table} set (${allowed.join(', ')})`);
    }
    if (seen.some((s) => s.id === b.id)) throw new RuleError('bad-placement', `ball ${b.id} is placed twice`);
    const problem = placementProblem(spec, seen, b.id, b, 'anywhere');
    if (problem) throw new RuleError('bad-placement', `ball ${b.id}: ${problem}`);
    seen.push({ id: b.id, x: b.x, y: b.y });
  }
}

/** Replace every ball on the table (an undoable step). */
export function setPracticeBalls(g: PracticeGame, player: PlayerId, balls: readonly Ball[]): void {
  assertPlayerOnTurn(g, player);
  checkLayout(specOfGame(g), g.table, balls);
  pushStep(g, null);
  g.balls = balls.map((b) => ({ id: b.id, x: b.x + 0, y: b.y + 0 })); // + 0: no -0 in the Game
  g.ballInHand = false;
}

/** Put one ball (on the table or not) at a place (an undoable step). */
export function movePracticeBall(g: PracticeGame, player: PlayerId, ball: Ball): void {
  const others = g.balls.filter((b) => b.id !== ball.id);
  setPracticeBalls(g, player, [...others, { id: ball.id, x: ball.x, y: ball.y }]);
}

/** Take one ball off the table (an undoable step). */
export function removePracticeBall(g: PracticeGame, player: PlayerId, id: string): void {
  if (!g.balls.some((b) => b.id === id)) throw new RuleError('bad-placement', `ball "${id}" is not on the table`);
  setPracticeBalls(g, player, g.balls.filter((b) => b.id !== id));
}

/** Go back one step (a shot or a placement). */
export function undoPractice(g: PracticeGame): void {
  const step = g.history.pop();
  if (!step) throw new RuleError('nothing-to-undo', 'there is nothing to undo');
  g.balls = step.balls;
  g.ballInHand = step.ballInHand;
  g.scores[g.turn] = step.score;
  if (step.shot) g.shots -= 1;
  g.verdict = null;
}

/** The recorded shots, each with the scene it was played from, oldest first: replay them through simulate(). */
export function practiceScript(g: PracticeGame): Array<{ scene: { table: TableName; balls: Ball[] }; shot: StrikeParams }> {
  const out: Array<{ scene: { table: TableName; balls: Ball[] }; shot: StrikeParams }> = [];
  for (const step of g.history) {
    if (!step.shot) continue;
    const { ball, heading, speed, side, top } = step.shot;
    out.push({ scene: { table: g.table, balls: step.balls.map((b) => ({ ...b })) }, shot: { ball, heading, speed, side, top } });
  }
  return out;
}
