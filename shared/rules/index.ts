// The referees' one entry point. Rules are a reducer, as in boardgame.io: applyShot(game, shot,
// outcome) returns the next Game and never changes its arguments; every random draw comes from the
// generator state kept in the Game. Illegal actions throw a RuleError and change nothing.
import { isTableName, type TableName } from '../physics/tables.ts';
import {
  assertNotOver,
  assertPlayerOnTurn,
  checkShot,
  clone,
  cueBallId,
  opponent,
  specOfGame,
  startVerdict,
} from './common.ts';
import { checkEightBallShot, eightBallTargets, judgeEightBall } from './eightball.ts';
import { RuleError } from './errors.ts';
import { checkNineBallShot, judgeNineBall, lowestBall } from './nineball.ts';
import { readOutcome } from './outcome.ts';
import { placementProblem } from './placement.ts';
import { rerack } from './pool.ts';
import {
  checkLayout,
  judgePractice,
  movePracticeBall,
  practiceCueBalls,
  practiceLayout,
  practiceScript,
  practiceTableAndLayout,
  removePracticeBall,
  setPracticeBalls,
  undoPractice,
} from './practice.ts';
import { caromSetup, eightBallRack, nineBallRack, POOL_CUE, snookerSetup } from './racks.ts';
import { seedState } from './rng.ts';
import { checkSnookerShot, judgeSnooker, snookerTargets } from './snooker.ts';
import { judgeThreeCushion } from './threecushion.ts';
import type {
  Ball,
  Choice,
  Game,
  GameBase,
  GameKind,
  NewGameOptions,
  Outcome,
  PlayerId,
  Point,
  PracticeGame,
  Shot,
  StrikeParams,
  Verdict,
} from './types.ts';

export type * from './types.ts';
export { RuleError } from './errors.ts';
export type { RuleErrorCode } from './errors.ts';
export { POCKETS, POCKET_SIDES, isPocketId } from './pockets.ts';
export { cueBallId } from './common.ts';
export { caromMarks, poolMarks, snookerMarks } from './marks.ts';
export { inArea, placementProblem } from './placement.ts';
export { isSnookered } from './snookered.ts';
export { ballValue } from './snooker.ts';
export { groupOf } from './eightball.ts';
export { countCarom } from './threecushion.ts';
export { readOutcome } from './outcome.ts';
export { seedState, nextUint32 } from './rng.ts';
export { ballSet } from './practice.ts';
export { playShot, shotClockExpired } from './play.ts';
export type { PlayedShot } from './play.ts';
export { replayMatch, achievements, tallyStep, tallied, EMPTY_TALLY } from './match-record.ts';
export type { MatchAction, MatchRecord, Replayed, Achievement, Tally } from './match-record.ts';
export { practiceRun, practiceStart, PRACTICE_KINDS, PRACTICE_MAX_SHOTS, PRACTICE_OPPONENT } from './practice-run.ts';
export type { PracticeKind, PracticeRun, PracticeShot } from './practice-run.ts';
export { SNOOKER_COLOURS, SNOOKER_REDS, SNOOKER_VALUES, POOL_OBJECT_BALLS, CAROM_BALLS } from './racks.ts';

export const GAME_KINDS: readonly GameKind[] = ['nineball', 'eightball', 'snooker', 'threecushion', 'practice'];

/** Points to win a three-cushion game when no raceTo is given. */
export const DEFAULT_CAROM_RACE = 15;

function checkPlayers(kind: GameKind, players: readonly PlayerId[]): PlayerId[] {
  if (!Array.isArray(players)) throw new RuleError('bad-player', 'players must be an array of ids');
  const want = kind === 'practice' ? 1 : 2;
  if (players.length !== want) {
    throw new RuleError('bad-player', `${kind} takes ${want} player${want === 1 ? '' : 's'}, got ${players.length}`);
  }
  for (const p of players) {
    if (typeof p !== 'string' || p.length === 0) throw new RuleError('bad-player', 'a player id must be a non-empty string');
  }
  if (new Set(players).size !== players.length) throw new RuleError('bad-player', 'player ids must be distinct');
  return [...players];
}

function checkRace(raceTo: unknown, fallback: number): number {
  if (raceTo === undefined) return fallback;
  if (typeof raceTo !== 'number' || !Number.isInteger(raceTo) || raceTo < 1) {
    throw new RuleError('bad-options', `raceTo must be a positive integer, got ${String(raceTo)}`);
  }
  return raceTo;
}

/**
 * A new game. The first player breaks (pool, snooker) or plays the white and opens (three-cushion).
 * Options: seed (number or string) for every random draw; raceTo (racks in pool, default 1; points
 * in three-cushion, default 15); for practice, table and layout.
 */
export function newGame(kind: GameKind, players: readonly PlayerId[], options: NewGameOptions = {}): Game {
  if (!GAME_KINDS.includes(kind)) throw new RuleError('bad-options', `unknown game kind "${String(kind)}"`);
  const ps = checkPlayers(kind, players);
  const seed = options.seed;
  if (seed !== undefined && typeof seed !== 'string' && (typeof seed !== 'number' || !Number.isFinite(seed))) {
    throw new RuleError('bad-options', 'seed must be a finite number or a string');
  }
  const first = ps[0] as PlayerId;
  const zero = (): Record<PlayerId, number> => Object.fromEntries(ps.map((p) => [p, 0]));
  const base = (table: TableName): Omit<GameBase, 'kind' | 'balls' | 'ballInHand'> => ({
    table,
    players: ps,
    turn: first,
    scores: zero(),
    winner: null,
    shots: 0,
    rng: seedState(seed),
    verdict: null,
    choices: [],
  });
  switch (kind) {
    case 'nineball': {
      const b = base('pool-9ft');
      const r = nineBallRack(specOfTable('pool-9ft'), b.rng);
      return { ...b, kind, balls: r.balls, rng: r.rng, ballInHand: 'kitchen', raceTo: checkRace(options.raceTo, 1), breaker: first, phase: 'break', fouls: zero() };
    }
    case 'eightball': {
      const b = base('pool-9ft');
      const r = eightBallRack(specOfTable('pool-9ft'), b.rng);
      return { ...b, kind, balls: r.balls, rng: r.rng, ballInHand: 'kitchen', raceTo: checkRace(options.raceTo, 1), breaker: first, phase: 'break', groups: null };
    }
    case 'snooker': {
      const b = base('snooker-12ft');
      return { ...b, kind, balls: snookerSetup(specOfTable('snooker-12ft')), ballInHand: 'D', on: 'red', freeBall: false, break: 0, respottedBlack: false, offender: null };
    }
    case 'threecushion': {
      const b = base('carom-match');
      return {
        ...b,
        kind,
        balls: caromSetup(specOfTable('carom-match')),
        ballInHand: false,
        raceTo: checkRace(options.raceTo, DEFAULT_CAROM_RACE),
        innings: Object.fromEntries(ps.map((p) => [p, p === first ? 1 : 0])),
        run: 0,
        highRun: zero(),
      };
    }
    case 'practice': {
      if (options.table !== undefined && !isTableName(options.table)) {
        throw new RuleError('bad-options', `unknown table "${String(options.table)}"`);
      }
      const { table, layout } = practiceTableAndLayout(options.table, options.layout);
      const b = base(table);
      const r = practiceLayout(specOfTable(table), layout, b.rng);
      return { ...b, kind, balls: r.balls, rng: r.rng, ballInHand: false, layout, history: [] };
    }
  }
}

function specOfTable(table: TableName) {
  return specOfGame({ table } as Game);
}

/**
 * Judge a shot: `outcome` is what the simulation returned for sceneOf(game) and strikeOf(shot)
 * (any object with its balls and events). Returns the next Game, whose `verdict` says what
 * happened. Shooting while `choices` are offered takes the default (plays on).
 */
export function applyShot(game: Game, shot: Shot, outcome: Outcome): Game {
  const allowed = game.kind === 'practice' ? practiceCueBalls(game) : [cueBallId(game)];
  checkShot(game, shot, allowed);
  if (game.kind === 'nineball') checkNineBallShot(game, shot);
  if (game.kind === 'eightball') checkEightBallShot(game, shot);
  if (game.kind === 'snooker') checkSnookerShot(game, shot);
  const facts = readOutcome(game.balls, shot.ball, outcome);
  const g = clone(game);
  const v = startVerdict(g, shot.player);
  switch (g.kind) {
    case 'nineball':
      judgeNineBall(g, shot, facts, v);
      break;
    case 'eightball':
      judgeEightBall(g, shot, facts, v);
      break;
    case 'snooker':
      judgeSnooker(g, shot, facts, v);
      break;
    case 'threecushion':
      judgeThreeCushion(g, shot, facts, v);
      break;
    case 'practice':
      judgePractice(g, shot, facts, v);
      break;
  }
  v.next = g.turn;
  g.verdict = v;
  return g;
}

/**
 * Place the cue ball in hand at p: the player must be on turn, the ball in hand, and p on the bed,
 * inside the area (`game.ballInHand`: anywhere, the kitchen, the D) and clear of other balls.
 * placeCueBall(game, p) places it for the player on turn.
 */
export function placeCueBall(game: Game, player: PlayerId, p: Point): Game;
export function placeCueBall(game: Game, p: Point): Game;
export function placeCueBall(game: Game, playerOrPoint: PlayerId | Point, point?: Point): Game {
  const player = typeof playerOrPoint === 'string' ? playerOrPoint : game.turn;
  const p = typeof playerOrPoint === 'string' ? point : playerOrPoint;
  assertNotOver(game);
  assertPlayerOnTurn(game, player);
  if (game.ballInHand === false) throw new RuleError('not-in-hand', `the cue ball is not in hand for ${player}`);
  if (!p || typeof p.x !== 'number' || typeof p.y !== 'number') throw new RuleError('bad-placement', 'the place must be { x, y }');
  const id = game.kind === 'practice' ? (practiceCueBalls(game)[0] as string) : cueBallId(game);
  const problem = placementProblem(specOfGame(game), game.balls, id, p, game.ballInHand);
  if (problem) throw new RuleError('bad-placement', `cannot place the cue ball: ${problem}`);
  const g = clone(game);
  g.balls = [{ id, x: p.x + 0, y: p.y + 0 }, ...g.balls.filter((b) => b.id !== id)];
  return g;
}

/** Alias of placeCueBall. */
export const placeBallInHand = placeCueBall;

/**
 * Take one of the offered `choices` instead of shooting:
 * - 'pass': nine-ball after a push-out, the pusher must shoot (WPA 2.4); snooker after a foul, the
 *   offender plays again and any free ball is void (WPBSA S3 Action after a Foul, Snookered after a
 *   Foul (f)); snooker re-spotted black, the winner of the lot lets the other play first;
 * - 'rerack': eight-ball after an illegal break or the 8 on the break: the balls are racked again
 *   (seeded) and the chooser breaks (WPA 3.3 (d), (e), (f));
 * - 'rerack-other': eight-ball after an illegal break: re-rack, and the offender breaks again.
 */
export function decide(game: Game, player: PlayerId, choice: Choice): Game {
  assertNotOver(game);
  assertPlayerOnTurn(game, player);
  if (!game.choices.includes(choice)) {
    throw new RuleError(
      'bad-choice',
      game.choices.length === 0 ? `there is no choice to make now (asked for "${String(choice)}")` :
        `"${String(choice)}" is not on offer; the choices are ${game.choices.join(', ')}`,
    );
  }
  const g = clone(game);
  const other = opponent(g, player);
  const v: Verdict = { ...startVerdict(g, player), shot: g.shots, continues: false };
  g.choices = [];
  if (choice === 'pass') {
    g.turn = other;
    if (g.kind === 'snooker') {
      g.freeBall = false;
      g.offender = null;
    }
    v.message = `${player} passes: ${other} to play`;
  } else if (g.kind === 'eightball') {
    const breaker = choice === 'rerack' ? player : other;
    rerack(g, breaker);
    v.message = `the balls are racked again; ${breaker} breaks`;
  }
  v.next = g.turn;
  g.verdict = v;
  return g;
}

/** The player concedes: the opponent wins the game (WPA 1.11 Concession; WPBSA S2 Frame (a)). */
export function concede(game: Game, player: PlayerId): Game {
  assertNotOver(game);
  if (!game.players.includes(player)) throw new RuleError('bad-player', `"${player}" is not a player of this game`);
  if (game.kind === 'practice') throw new RuleError('bad-choice', 'there is nobody to concede to in practice');
  const g = clone(game);
  const other = opponent(g, player);
  g.winner = other;
  g.choices = [];
  g.verdict = { ...startVerdict(g, player), shot: g.shots, next: g.turn, rackWinner: other, loss: 'concession', message: `${player} concedes; ${other} wins` };
  return g;
}

/**
 * The player claims the game of an opponent who left (their seat's hold ran out): scored as the
 * opponent's concession, and said as what it is.
 */
export function claimGame(game: Game, player: PlayerId): Game {
  if (!game.players.includes(player)) throw new RuleError('bad-player', `"${player}" is not a player of this game`);
  const absent = opponent(game, player);
  const g = concede(game, absent);
  g.verdict = { ...g.verdict!, message: `${player} claims the game: ${absent} has left; ${player} wins` };
  return g;
}

/** The balls the player on turn may legally meet first (for a bot or the display). */
export function legalTargets(game: Game): string[] {
  switch (game.kind) {
    case 'nineball': {
      const low = lowestBall(game);
      return low === null ? [] : [low];
    }
    case 'eightball':
      return eightBallTargets(game);
    case 'snooker':
      return snookerTargets(game);
    case 'threecushion': {
      const cue = cueBallId(game);
      return game.balls.filter((b) => b.id !== cue).map((b) => b.id);
    }
    case 'practice': {
      const cues = practiceCueBalls(game);
      return game.balls.filter((b) => !cues.includes(b.id)).map((b) => b.id);
    }
  }
}

/** The scene to hand to simulate(): the table and the balls on it. */
export function sceneOf(game: Game): { table: TableName; balls: Ball[] } {
  return { table: game.table, balls: game.balls.map((b) => ({ id: b.id, x: b.x, y: b.y })) };
}

/** The simulation's shot from a referee's shot (the declarations dropped). */
export function strikeOf(shot: Shot): StrikeParams {
  return { ball: shot.ball, heading: shot.heading, speed: shot.speed, side: shot.side, top: shot.top };
}

/** Fold a sequence of shots and their outcomes over a game (the replay of a recorded game). */
export function replay(start: Game, steps: ReadonlyArray<{ shot: Shot; outcome: Outcome }>): Game {
  let g = start;
  for (const s of steps) g = applyShot(g, s.shot, s.outcome);
  return g;
}

function asPractice(game: Game, what: string): PracticeGame {
  if (game.kind !== 'practice') throw new RuleError('bad-choice', `${what} is only for practice, not ${game.kind}`);
  return game;
}

/** Practice: undo the last shot or placement. */
export function undo(game: Game): Game {
  const g = clone(asPractice(game, 'undo'));
  undoPractice(g);
  return g;
}

/** Practice: replace every ball on the table by `balls` (validated: known ids, on the bed, no overlap). */
export function placeBalls(game: Game, player: PlayerId, balls: readonly Ball[]): Game {
  const g = clone(asPractice(game, 'free placement'));
  setPracticeBalls(g, player, balls);
  return g;
}

/** Practice: put one ball (on the table or taken from the set) at a place. */
export function placeBall(game: Game, player: PlayerId, ball: Ball): Game {
  const g = clone(asPractice(game, 'free placement'));
  movePracticeBall(g, player, ball);
  return g;
}

/** Practice: take one ball off the table. */
export function removeBall(game: Game, player: PlayerId, id: string): Game {
  const g = clone(asPractice(game, 'free placement'));
  removePracticeBall(g, player, id);
  return g;
}

/** Practice: the recorded shots with the scenes they were played from, to replay through simulate(). */
export function replayScript(game: Game): ReturnType<typeof practiceScript> {
  return practiceScript(asPractice(game, 'replay'));
}

export { checkLayout, POOL_CUE };
