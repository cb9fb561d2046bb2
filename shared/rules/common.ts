// Helpers every referee uses: copying the game, checking who shoots and with which ball, the
// verdict record, and putting the cue ball in hand.
import { tableSpec, type TableSpec } from '../physics/tables.ts';
import { RuleError } from './errors.ts';
import { freeSpot } from './placement.ts';
import type { Ball, BallInHand, Game, PlayerId, Shot, Verdict } from './types.ts';

/** A deep copy of plain JSON data: the referees change the copy, never what they were given. */
export function clone<T>(value: T): T {
  return structuredClone(value);
}

export function specOfGame(game: Game): TableSpec {
  return tableSpec(game.table);
}

/** The player after p (two-player games). */
export function opponent(game: Game, p: PlayerId): PlayerId {
  if (game.players.length < 2) return p;
  return game.players[0] === p ? (game.players[1] as PlayerId) : (game.players[0] as PlayerId);
}

/** The ball the player on turn must strike: 'cue', or in three-cushion the player's own ball. */
export function cueBallId(game: Game): string {
  if (game.kind === 'threecushion') return game.players[0] === game.turn ? 'white' : 'yellow';
  if (game.kind === 'practice' && game.table === 'carom-match') {
    return game.balls.some((b) => b.id === 'white') ? 'white' : 'yellow';
  }
  return 'cue';
}

export function assertNotOver(game: Game): void {
  if (game.winner !== null) throw new RuleError('game-over', `the game is over: ${game.winner} has won`);
}

export function assertPlayerOnTurn(game: Game, player: PlayerId): void {
  if (!game.players.includes(player)) {
    throw new RuleError('bad-player', `"${player}" is not a player of this game (${game.players.join(', ')})`);
  }
  if (player !== game.turn) throw new RuleError('wrong-player', `it is ${game.turn}'s turn, not ${player}'s`);
}

const DECLARATIONS: ReadonlyArray<[keyof Shot, Game['kind'], string]> = [
  ['pushOut', 'nineball', 'a push-out is a nine-ball declaration'],
  ['calledPocket', 'eightball', 'a called pocket is an eight-ball declaration'],
  ['calledBall', 'eightball', 'a called ball is an eight-ball declaration'],
  ['nominated', 'snooker', 'a nominated ball is a snooker declaration'],
];

/** The checks every shot passes before any game's rules: game on, player on turn, sane numbers, ball. */
export function checkShot(game: Game, shot: Shot, allowedBalls: readonly string[] = [cueBallId(game)]): void {
  assertNotOver(game);
  if (!shot || typeof shot !== 'object') throw new RuleError('bad-shot', 'the shot must be an object');
  assertPlayerOnTurn(game, shot.player);
  for (const k of ['heading', 'speed', 'side', 'top'] as const) {
    if (typeof shot[k] !== 'number' || !Number.isFinite(shot[k])) {
      throw new RuleError('bad-shot', `shot.${k} must be a finite number, got ${String(shot[k])}`);
    }
  }
  if (shot.speed < 0) throw new RuleError('bad-shot', `shot.speed must not be negative, got ${shot.speed}`);
  if (!allowedBalls.includes(shot.ball)) {
    throw new RuleError('wrong-ball', `${shot.player} must strike ${allowedBalls.join(' or ')}, not "${shot.ball}"`);
  }
  if (!game.balls.some((b) => b.id === shot.ball)) {
    throw new RuleError('wrong-ball', `ball "${shot.ball}" is not on the table`);
  }
  for (const [key, kind, what] of DECLARATIONS) {
    const v = shot[key];
    if (v !== undefined && v !== false && game.kind !== kind) {
      throw new RuleError('bad-declaration', `${what}; it does not apply to ${game.kind}`);
    }
  }
}

export function zeroPoints(game: Game): Record<PlayerId, number> {
  return Object.fromEntries(game.players.map((p) => [p, 0]));
}

/** A verdict to fill in, for the shot the game is about to count. */
export function startVerdict(game: Game, player: PlayerId): Verdict {
  return {
    shot: game.shots + 1,
    player,
    foul: false,
    reason: null,
    fouls: [],
    points: zeroPoints(game),
    potted: [],
    spotted: [],
    continues: false,
    next: player,
    message: '',
  };
}

export function addFoul(v: Verdict, code: string): void {
  if (!v.fouls.includes(code)) v.fouls.push(code);
  v.foul = true;
  if (v.reason === null) v.reason = code;
}

/** Take ball `id` off `balls` and put it in hand in `area`, at a free place near the usual spot. */
export function putInHand(spec: TableSpec, balls: Ball[], id: string, area: Exclude<BallInHand, false>): Ball[] {
  const rest = balls.filter((b) => b.id !== id);
  const p = freeSpot(spec, rest, id, area);
  return [{ id, x: p.x, y: p.y }, ...rest];
}

export function describeList(ids: readonly string[]): string {
  return ids.length === 0 ? 'nothing' : ids.join(', ');
}
