// A room: its plain state (persisted as JSON after every change) and the pure steps of its match:
// starting a game, moving on after a move (snooker frames, the end of the match), the view sent out.
import { SHOT_CLOCK_MIN_S, type GameKindName, type PlayerRef, type RoomView } from '../../shared/protocol/index.ts';
import { newGame, tallyStep, type Game, type Tally } from '../../shared/rules/index.ts';
import type { ConnId } from './lobby.ts';
import type { Level } from '../../shared/ai/index.ts';
import type { UnratedReason } from '../ratings/policy.ts';

export type RoomStatus = 'waiting' | 'playing' | 'over' | 'closed';

/** Everything about a room that survives a restart. */
export interface RoomState {
  readonly id: string;
  readonly kind: GameKindName;
  readonly raceTo: number;
  readonly private: boolean;
  readonly shotClock: number;
  readonly guidance: 'none' | 'contact' | 'path';
  readonly createdBy: string;
  readonly seats: readonly PlayerRef[];
  readonly status: RoomStatus;
  readonly stateId: number;
  readonly game: Game | null;
  readonly matchId: number | null;
  /** The match's players, the first breaking its first game (and snooker's even frames). */
  readonly order: readonly string[];
  /** The match's seed; snooker frame n plays seed + n. */
  readonly seed: number;
  readonly frame: number;
  /** Snooker frames won in the match. */
  readonly frames: Readonly<Record<string, number>> | null;
  readonly deadline: number | null;
  readonly rematch: readonly string[];
  readonly winner: string | null;
  /** How the match ended: 'played', 'concession', 'claim'. */
  readonly how: string | null;
  /** Once over: players who have left, and when the room closes by itself (ms since the epoch). */
  readonly left: readonly string[];
  readonly closesAt: number | null;
  /** What the match has achieved so far (snooker breaks, three-cushion runs, nine-ball break-and-runs). */
  readonly tally: Tally;
  /** The computer's seat, when the room plays the computer (absent in rooms stored before). */
  readonly computer?: { readonly id: string; readonly level: Level } | null;
}

/** How long a finished room stays open for a rematch or a last word (ms). */
export const OVER_KEEP_MS = 10 * 60 * 1000;

export class Room {
  /** Sockets watching as spectators. */
  readonly spectators = new Set<ConnId>();
  /** Players whose seat hold has run out and whose opponent has been told so. */
  readonly holdsOver = new Set<string>();
  /** The computer's decision being made for this state id, and the timer that plays it. */
  thinking: { stateId: number; timer?: NodeJS.Timeout } | null = null;
  /** When the balls of the last shot stop (ms since the epoch): the computer's pause counts from there. */
  stillAt = 0;
  /** Whether the finished match counted for the ratings, as stored (kept here so a view needs no read). */
  outcome: { readonly rated: boolean; readonly unrated: UnratedReason | null } | null = null;
  /** A tick's timers are queued for the room: the next tick does not queue them again. */
  timersQueued = false;
  /** Several processes: the process that owns the room (runs its commands and clocks); undefined: not known. */
  owner: string | undefined = undefined;
  /** Several processes: what the owner last announced of the room (its summary), so that a shot is not announced. */
  announced = '';

  constructor(public state: RoomState) {}
}

/** The match's first game, or snooker's frame n: the break alternates from frame to frame. */
export function gameFor(state: RoomState, frame: number): Game {
  if (state.kind !== 'snooker') return newGame(state.kind, state.order, { seed: state.seed, raceTo: state.raceTo });
  const players = frame % 2 === 0 ? state.order : [...state.order].reverse();
  return newGame('snooker', players, { seed: state.seed + frame });
}

/**
 * The shot clock's end after a change that leaves a game in play, the clock starting at `from`. A
 * room stored before clocks under SHOT_CLOCK_MIN_S were refused gets the minimum, not a foul a tick.
 */
export function deadlineAfter(state: RoomState, from: number): number | null {
  return state.status === 'playing' && state.shotClock > 0 ? from + Math.max(state.shotClock, SHOT_CLOCK_MIN_S) * 1000 : null;
}

/**
 * The room after a move produced `game`: a snooker frame won starts the next (the other player
 * breaks) until the race of frames is won; any other game's end ends the match. The next
 * player's clock starts at `clockFrom` (after a shot, once its balls have stopped).
 */
export function afterMove(before: RoomState, game: Game, how: string, now: number, clockFrom = now): RoomState {
  const state = before.game === null ? before : { ...before, tally: tallyStep(before.tally, before.game, game) };
  const stateId = state.stateId + 1;
  if (game.winner === null) {
    const next = { ...state, game, stateId };
    return { ...next, deadline: deadlineAfter(next, clockFrom) };
  }
  if (state.kind === 'snooker' && how === 'played') {
    const frames = { ...(state.frames ?? {}) };
    frames[game.winner] = (frames[game.winner] ?? 0) + 1;
    if (frames[game.winner]! < state.raceTo) {
      const frame = state.frame + 1;
      const next: RoomState = { ...state, frames, frame, stateId, game: gameFor(state, frame) };
      return { ...next, deadline: deadlineAfter(next, clockFrom) };
    }
    return over({ ...state, frames, game, stateId }, game.winner, how, now);
  }
  const frames = state.kind === 'snooker' ? { ...(state.frames ?? {}), [game.winner]: (state.frames?.[game.winner] ?? 0) + 1 } : state.frames;
  return over({ ...state, frames, game, stateId }, game.winner, how, now);
}

function over(state: RoomState, winner: string, how: string, now: number): RoomState {
  return { ...state, status: 'over', winner, how, deadline: null, rematch: [], left: [], closesAt: now + OVER_KEEP_MS };
}

export function roomView(room: Room, seat: (p: PlayerRef) => { connected: boolean; heldUntil?: number }): RoomView {
  const s = room.state;
  return {
    id: s.id,
    kind: s.kind,
    raceTo: s.raceTo,
    private: s.private,
    shotClock: s.shotClock,
    guidance: s.guidance ?? 'contact',
    players: s.seats.map((p) => ({ id: p.id, name: p.name, ...seat(p) })),
    spectators: room.spectators.size,
    status: s.status === 'closed' ? 'over' : s.status,
    stateId: s.stateId,
    game: s.game,
    ...(s.matchId === null ? {} : { match: s.matchId }),
    ...(s.deadline === null ? {} : { deadline: s.deadline }),
    ...(s.frames === null ? {} : { frames: s.frames }),
    ...(s.status === 'over' ? { rematch: s.rematch, winner: s.winner } : {}),
  };
}
