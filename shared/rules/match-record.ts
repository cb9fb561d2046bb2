// A match as a record anyone can check: the Game at the start and every action that changed it,
// replayed with the shared rules and physics. Each shot's outcome hash comes out of the replay, to
// compare with what the server broadcast; the achievements (snooker breaks, three-cushion runs,
// nine-ball break-and-runs) are read from the games the replay passes through.
import { claimGame, concede, decide, newGame, placeCueBall } from './index.ts';
import { opponent } from './common.ts';
import { playShot, shotClockExpired } from './play.ts';
import type { Choice, Game, PlayerId, Point, StrikeParams } from './types.ts';

export type MatchAction =
  | { type: 'shot'; player: PlayerId; shot: Omit<StrikeParams, never> & Record<string, unknown>; cueBall?: Point; hash?: string }
  | { type: 'place'; player: PlayerId; cueBall: Point }
  | { type: 'decide'; player: PlayerId; choice: Choice }
  | { type: 'concede'; player: PlayerId }
  /** The player claims the game of an opponent whose seat hold ran out. */
  | { type: 'claim'; player: PlayerId }
  /** The player on turn ran out of time. */
  | { type: 'clock'; player: PlayerId }
  /** Snooker: the next frame of the match, `players[0]` breaking. */
  | { type: 'frame'; players: PlayerId[]; seed: number };

export interface MatchRecord {
  readonly start: Game;
  readonly actions: readonly MatchAction[];
}

export interface Replayed {
  /** The game after the last action. */
  readonly game: Game;
  /** The game after each action, in order (a frame action gives the new frame's start). */
  readonly games: readonly Game[];
  /** Each shot's outcome hash as the replay computed it, and the hash the record claims. */
  readonly shots: readonly { readonly index: number; readonly hash: string; readonly recorded?: string }[];
}

/** Replays a match record; throws a RuleError (or the physics' error) at an action the rules refuse. */
export function replayMatch(record: MatchRecord): Replayed {
  let game = record.start;
  const games: Game[] = [];
  const shots: { index: number; hash: string; recorded?: string }[] = [];
  record.actions.forEach((a, index) => {
    switch (a.type) {
      case 'shot': {
        const { player: _p, ...stroke } = a.shot;
        const played = playShot(game, { ...(stroke as unknown as StrikeParams), player: a.player }, a.cueBall);
        shots.push({ index, hash: played.outcome.hash, ...(a.hash === undefined ? {} : { recorded: a.hash }) });
        game = played.game;
        break;
      }
      case 'place':
        game = placeCueBall(game, a.player, a.cueBall);
        break;
      case 'decide':
        game = decide(game, a.player, a.choice);
        break;
      case 'concede':
        game = concede(game, a.player);
        break;
      case 'claim':
        game = claimGame(game, a.player);
        break;
      case 'clock':
        game = shotClockExpired(game);
        break;
      case 'frame':
        game = newGame('snooker', a.players, { seed: a.seed });
        break;
    }
    games.push(game);
  });
  return { game, games, shots };
}

export interface Achievement {
  readonly player: PlayerId;
  /** 'break' (snooker, points), 'run' (three-cushion, points), 'break-and-run' (nine-ball, shots taken). */
  readonly what: 'break' | 'run' | 'break-and-run';
  readonly value: number;
}

/** What a match has achieved so far, as plain data: folded game by game (tallyStep), read at the end (tallied). */
export interface Tally {
  /** Each player's best snooker break or three-cushion run so far. */
  readonly best: Readonly<Record<PlayerId, number>>;
  /** Nine-ball: the rack in play, from its break. */
  readonly rack: { readonly breaker: PlayerId; readonly clean: boolean; readonly shots: number } | null;
  /** Nine-ball break-and-runs so far. */
  readonly runs: readonly Achievement[];
}

export const EMPTY_TALLY: Tally = { best: {}, rack: null, runs: [] };

/**
 * The tally after the game went from `prev` to `g` by one action: a scoring snooker visit's break
 * so far, each three-cushion player's high run, and a nine-ball rack won by its breaker with no
 * shot by the opponent (its value the shots it took, fewer being better).
 */
export function tallyStep(t: Tally, prev: Game, g: Game): Tally {
  const v = g.verdict;
  let best = t.best;
  const keep = (p: PlayerId, value: number) => {
    if (value > (best[p] ?? 0)) best = { ...best, [p]: value };
  };
  if (g.kind === 'snooker' && v && !v.foul && (v.points[v.player] ?? 0) > 0) keep(v.player, g.break);
  if (g.kind === 'threecushion') for (const p of g.players) keep(p, g.highRun[p] ?? 0);
  let rack = t.rack;
  let runs = t.runs;
  if (g.kind === 'nineball' && prev.kind === 'nineball' && v && g.shots > prev.shots) {
    if (prev.phase === 'break') rack = { breaker: prev.breaker, clean: true, shots: 0 };
    if (rack) {
      rack = { ...rack, shots: rack.shots + 1, clean: rack.clean && v.player === rack.breaker };
      if (v.rackWinner !== undefined) {
        if (rack.clean && v.rackWinner === rack.breaker && v.loss === undefined) runs = [...runs, { player: rack.breaker, what: 'break-and-run', value: rack.shots }];
        rack = null;
      }
    }
  }
  return best === t.best && rack === t.rack && runs === t.runs ? t : { best, rack, runs };
}

/** The achievements of a tally: each player's best break or run, and every break-and-run. */
export function tallied(kind: Game['kind'], t: Tally): Achievement[] {
  const what: Achievement['what'] | null = kind === 'snooker' ? 'break' : kind === 'threecushion' ? 'run' : null;
  const best: Achievement[] = what ? Object.entries(t.best).map(([player, value]) => ({ player, what, value })) : [];
  return [...t.runs, ...best];
}

/** The achievements of a sequence of games from its start (a replay's or a practice run's). */
export function achievements(start: Game, games: readonly Game[]): Achievement[] {
  let t = EMPTY_TALLY;
  let prev = start;
  for (const g of games) {
    t = tallyStep(t, prev, g);
    prev = g;
  }
  return tallied(start.kind, t);
}
