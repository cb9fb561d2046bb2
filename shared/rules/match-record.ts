// A match as a record anyone can check: the Game at the start and every action that changed it,
// replayed with the shared rules and physics. Each shot's outcome hash comes out of the replay, to
// compare with what the server broadcast; the achievements (snooker breaks, three-cushion runs,
// nine-ball break-and-runs) are read from the games the replay passes through.
import { concede, decide, newGame, placeCueBall } from './index.ts';
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
        game = concede(game, opponent(game, a.player));
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

/**
 * The best achievement of each player in a sequence of games (a replay's, from its start): the
 * highest snooker break, the longest three-cushion run, and every nine-ball rack won by its breaker
 * with no shot by the opponent (its value the shots it took, fewer being better).
 */
export function achievements(start: Game, games: readonly Game[]): Achievement[] {
  const out: Achievement[] = [];
  const best = new Map<PlayerId, number>();
  const keep = (p: PlayerId, v: number) => {
    if (v > (best.get(p) ?? 0)) best.set(p, v);
  };
  let prev = start;
  let rack: { breaker: PlayerId; clean: boolean; shots: number } | null = null;
  for (const g of games) {
    const v = g.verdict;
    // A scoring visit's break so far, after each of its pots.
    if (g.kind === 'snooker' && v && !v.foul && (v.points[v.player] ?? 0) > 0) keep(v.player, g.break);
    if (g.kind === 'threecushion') for (const p of g.players) keep(p, g.highRun[p] ?? 0);
    if (g.kind === 'nineball' && prev.kind === 'nineball' && v && g.shots > prev.shots) {
      if (prev.phase === 'break') rack = { breaker: prev.breaker, clean: true, shots: 0 };
      if (rack) {
        rack.shots++;
        if (v.player !== rack.breaker) rack.clean = false;
        if (v.rackWinner !== undefined) {
          if (rack.clean && v.rackWinner === rack.breaker && v.loss === undefined) out.push({ player: rack.breaker, what: 'break-and-run', value: rack.shots });
          rack = null;
        }
      }
    }
    prev = g;
  }
  const what = start.kind === 'snooker' ? 'break' : start.kind === 'threecushion' ? 'run' : null;
  if (what) for (const [player, value] of best) out.push({ player, what, value });
  return out;
}
