// What the server sends. Plain types: the server builds them, clients read them.
import type { SimEvent } from '../physics/index.ts';
import type { Game } from '../rules/index.ts';
import type { GameKindName, ShotInput } from './client-messages.ts';

export interface PlayerRef {
  readonly id: string;
  readonly name: string;
}

/** A seated player, with whether any of their sockets is connected and, if not, until when the seat is held (ms since the epoch). */
export interface SeatView extends PlayerRef {
  readonly connected: boolean;
  readonly heldUntil?: number;
}

export type RoomStatus = 'waiting' | 'playing' | 'over';

export interface RoomView {
  readonly id: string;
  readonly kind: GameKindName;
  readonly raceTo: number;
  readonly private: boolean;
  /** Seconds per shot, 0 for none. */
  readonly shotClock: number;
  /** How much the players' pages show before a shot: 'none', 'contact' or 'path'. */
  readonly guidance: 'none' | 'contact' | 'path';
  readonly players: readonly SeatView[];
  /** Number of spectators. */
  readonly spectators: number;
  readonly status: RoomStatus;
  /** Counts every change of `game`; a move must carry the current one. */
  readonly stateId: number;
  /** The rules' Game (players are player ids); null while waiting. */
  readonly game: Game | null;
  /** The match in play or last played here: its record is GET /api/matches/:id. */
  readonly match?: number;
  /** The shot clock's end for the player on turn (ms since the epoch). */
  readonly deadline?: number;
  /** Snooker frames won in this match (snooker's raceTo counts frames); the pool and carom games keep their own race. */
  readonly frames?: Readonly<Record<string, number>>;
  /** Players who asked for a rematch once the game is over. */
  readonly rematch?: readonly string[];
  /** The winner, once over. */
  readonly winner?: string | null;
  /** Once over: whether the match counts for the ratings (docs/api.md, "Ratings"). */
  readonly rated?: boolean;
  /** Once over and not rated: why, as words that finish "Not rated: ..." (e.g. "each player must take at least 3 shots"). */
  readonly unrated?: string;
}

export interface LobbyRoom {
  readonly id: string;
  readonly kind: GameKindName;
  readonly raceTo: number;
  readonly players: readonly PlayerRef[];
  readonly spectators: number;
  readonly status: RoomStatus;
}

/** The server's outcome of simulate(sceneOf(game), shot): everything but the paths, which a client recomputes. */
export interface OutcomeView {
  readonly hash: string;
  readonly balls: readonly { readonly id: string; readonly x: number; readonly y: number; readonly pocketed: boolean; readonly pocket?: string }[];
  readonly events: readonly SimEvent[];
  readonly duration: number;
}

export type ServerMessage =
  | { readonly type: 'welcome'; readonly re?: string | number; readonly player: PlayerRef; readonly token: string }
  /** The player's own name changed (a rename, on every socket of theirs). */
  | { readonly type: 'player'; readonly re?: string | number; readonly player: PlayerRef }
  /** At most LOBBY_MAX_ROOMS rooms, waiting ones first; `more` counts the public rooms not listed. */
  | { readonly type: 'lobby'; readonly re?: string | number; readonly rooms: readonly LobbyRoom[]; readonly more: number; readonly online: readonly PlayerRef[] }
  | { readonly type: 'room'; readonly re?: string | number; readonly room: RoomView }
  | {
      readonly type: 'shot';
      readonly re?: string | number;
      readonly room: string;
      /** The match the shot belongs to (GET /api/matches/:id). */
      readonly match: number;
      readonly stateId: number;
      /** The shot as simulated, with its player. */
      readonly shot: ShotInput & { readonly player: string };
      /** Where the ball in hand was placed first, if it was. */
      readonly cueBall?: { readonly x: number; readonly y: number };
      readonly outcome: OutcomeView;
      readonly game: Game;
      readonly deadline?: number;
    }
  | { readonly type: 'chat'; readonly re?: string | number; readonly room: string; readonly from: PlayerRef; readonly text: string; readonly at: number }
  | { readonly type: 'left'; readonly re?: string | number; readonly room: string }
  | { readonly type: 'error'; readonly re?: string | number; readonly code: ErrorCode; readonly message: string };

export type ErrorCode =
  | 'bad-json'
  | 'bad-message'
  | 'not-welcomed'
  | 'bad-token'
  | 'name-taken'
  | 'no-room'
  | 'room-full'
  | 'not-seated'
  | 'not-playing'
  | 'stale-state'
  | 'not-your-turn'
  | 'too-many-rooms'
  | 'not-claimable'
  // Limits (issue 36): too many of something from one player or address, or too fast.
  | 'rate-limited'
  | 'too-many-guests'
  | 'too-many-tabs'
  | 'bad-name'
  | 'bad-shot'
  | 'miscue'
  | 'internal'
  // Several processes (docs/scale.md): the room's process did not answer or is being replaced; try again.
  | 'unavailable'
  // The referees' own codes (shared/rules RuleError), passed through.
  | 'game-over'
  | 'wrong-player'
  | 'bad-player'
  | 'wrong-ball'
  | 'bad-declaration'
  | 'bad-placement'
  | 'not-in-hand'
  | 'bad-choice'
  | 'bad-outcome'
  | 'bad-options';
