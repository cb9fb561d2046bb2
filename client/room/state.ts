// The room page's state (RoomPageState: plain data, changed only by reducer.ts), what made the
// verdict shown (read from the games before and after it), and the players' ratings.
import type { RoomView } from '../../shared/protocol/index.ts';
import type { Game, PlayerId } from '../../shared/rules/index.ts';
import type { VerdictHow } from '../verdict.ts';
import type { RatingChange } from './result.ts';

export type RoomRatings = Record<string, RatingChange>;

/**
 * What made `after`'s verdict, from the game before it: a broadcast stroke (with its
 * declarations); else a concession or claim; a verdict that counted a shot without a stroke is
 * the shot clock; one that did not is a choice (a pass, or an eight-ball re-rack). null: the
 * verdict is the one `before` had.
 */
export function howOf(before: Game | null, after: Game, shot?: { readonly pushOut?: boolean; readonly calledPocket?: string }, claimed = false): VerdictHow | null {
  const v = after.verdict;
  if (!v) return {};
  // The same verdict (a placement, a reconnection): what made it is unchanged.
  if (!shot && before?.verdict && before.verdict.shot === v.shot && before.verdict.message === v.message && before.verdict.player === v.player) return null;
  const known = before ?? undefined;
  if (shot) return { action: 'shot', shot, ...(known ? { before: known } : {}) };
  if (v.loss === 'concession') return { action: claimed ? 'claim' : 'concede' };
  if (!before) return {};
  if (after.shots > before.shots) return { action: 'clock', before };
  return { action: 'decide', choice: after.kind === 'eightball' ? 'rerack' : 'pass' };
}

/** A chat line as the log shows it. */
export interface ChatLine {
  readonly from: string;
  readonly text: string;
}

/**
 * Everything the room page shows, as plain data: what the server said (the room, the game this
 * page holds or predicts) and what the player did. Changed only by `reduce` (reducer.ts); drawn
 * by render.ts; the page (pages/room.ts) runs the effects it implies.
 */
export interface RoomPageState {
  readonly id: string;
  /** This page's player, and whether the connection is down (no shot meanwhile). */
  readonly me: PlayerId | undefined;
  readonly reconnecting: boolean;
  readonly room: RoomView | null;
  /** A room message that came while a shot played, applied once it has. */
  readonly pendingRoom: RoomView | null;
  /** The game and stateId this page shows (the server's, or its own prediction of it). */
  readonly game: Game | null;
  readonly stateId: number;
  /** A shot of this page's in flight, or shots being animated: no new shot meanwhile. */
  readonly busy: boolean;
  /** The shot clock's end, from the last room or shot message (ms since the epoch). */
  readonly deadline: number | undefined;
  /** When "Concede" was clicked once, and when a second click confirmed it (ms since the epoch). */
  readonly concedeArmedAt: number;
  readonly concededAt: number | undefined;
  /** What made the verdict shown (a stroke and its declarations, the clock, a concession...). */
  readonly how: VerdictHow;
  /** The players' ratings in this kind; the match they are for, and the matches whose ratings before and after are wanted. */
  readonly ratings: RoomRatings;
  readonly ratedMatch: number | undefined;
  readonly ratedBefore: number | undefined;
  readonly ratedAfter: number | undefined;
  /** Said in place of the referee's words until the game changes ("Call a pocket for the 8 first."). */
  readonly notice: string;
  readonly chat: readonly ChatLine[];
  /** Ids of this page's chat lines in flight, and what was said of the last one refused. */
  readonly chatSent: readonly string[];
  readonly chatNote: string;
  /** The server does not know this room. */
  readonly missing: boolean;
}

export function initialRoomState(id: string, me?: PlayerId): RoomPageState {
  return {
    id,
    me,
    reconnecting: false,
    room: null,
    pendingRoom: null,
    game: null,
    stateId: -1,
    busy: false,
    deadline: undefined,
    concedeArmedAt: -Infinity,
    concededAt: undefined,
    how: {},
    ratings: {},
    ratedMatch: undefined,
    ratedBefore: undefined,
    ratedAfter: undefined,
    notice: '',
    chat: [],
    chatSent: [],
    chatNote: '',
    missing: false,
  };
}

/** How long a first click on "Concede" waits for the second (ms). */
export const CONFIRM_MS = 4000;

export const seated = (s: RoomPageState): boolean => !!s.room?.players.some((p) => p.id === s.me);

/** The player may shoot now (not while a shot plays, nor while the server could not take one). */
export const myTurn = (s: RoomPageState): boolean =>
  !!s.game && s.room?.status === 'playing' && s.game.winner === null && s.game.turn === s.me && seated(s) && !s.busy && !s.reconnecting;

export const nameOf = (s: RoomPageState) => (pid: string): string => s.room?.players.find((p) => p.id === pid)?.name ?? pid;

/** A first click on "Concede" is waiting for its second. */
export const concedeArmed = (s: RoomPageState, now: number): boolean => now - s.concedeArmedAt < CONFIRM_MS;
