// The store's rows, inputs and rules shared by its implementations (SQLite and PostgreSQL).
import type { UnratedReason } from '../ratings/policy.ts';
import { MAX_OPEN_ROOMS_PER_PLAYER } from '../../shared/protocol/index.ts';

export interface PlayerRow {
  readonly id: number;
  readonly name: string;
}

/** Players a pass of the pruner looked at: those it may delete, and where the next batch starts. */
export interface IdlePage {
  readonly idle: number[];
  /** The id after which the next batch starts; undefined when the pass is done. */
  readonly next: number | undefined;
}

/** What makes a key of a name taken before this release unique (see fillNameKeys). */
export const LEGACY_KEY = '\u0001';

export interface RoomRow {
  readonly id: string;
  readonly status: string;
  readonly state: string;
}

export interface NewRoom {
  readonly id: string;
  readonly kind: string;
  readonly raceTo: number;
  readonly private: boolean;
  readonly shotClock: number;
  readonly createdBy: number;
  readonly status: string;
  readonly state: string;
}

export interface NewMatch {
  readonly roomId: string;
  readonly kind: string;
  readonly raceTo: number;
  readonly player1: number;
  readonly player2: number;
  readonly seed: number;
  /** The rules' Game at the start, JSON. */
  readonly start: string;
}

/** A verified achievement; `better` sorts it, higher first. */
export interface RecordRow {
  readonly what: string;
  readonly player: number;
  readonly value: number;
  readonly better: number;
}

export interface MatchResult {
  readonly matchId: number;
  readonly kind: string;
  readonly winner: number;
  readonly loser: number;
  readonly how: string;
  readonly scores: string;
  /**
   * Whether the game was real enough to move the ratings (the service's rules: shots, time); the
   * store may still leave it unrated for the pair's daily limit.
   */
  readonly rated: boolean;
  /** Why not, when `rated` is false. */
  readonly unrated?: UnratedReason;
  readonly records: readonly RecordRow[];
}

/** One change of a room: its new snapshot, and the action that made it in its match's log. */
export interface RoomChange {
  readonly roomId: string;
  readonly status: string;
  readonly state: string;
  readonly action?: { readonly matchId: number; readonly seq: number; readonly json: string };
  readonly result?: MatchResult;
  /**
   * The stateId the stored room must be at (its state's `stateId`) for this change to be written:
   * the one its writer read. Otherwise the whole save is refused with a StaleRoomError and nothing
   * is written, so that of two writers of one room only the first commits. Unset: no check.
   */
  readonly expectStateId?: number;
}

/** Thrown by saveChanges and startMatch when a room is not at the stateId a change expects; nothing is written. */
export class StaleRoomError extends Error {
  constructor(
    readonly roomId: string,
    readonly expected: number,
  ) {
    super(`room ${roomId} is no longer at stateId ${expected}: another writer changed it first`);
  }
}

/** Rooms waiting or in play one player may have created at once; createRoom refuses another. */
export const OPEN_ROOMS_PER_PLAYER = MAX_OPEN_ROOMS_PER_PLAYER;

/** Thrown by createRoom when its creator has OPEN_ROOMS_PER_PLAYER open rooms already; nothing is written. */
export class TooManyRoomsError extends Error {
  constructor(readonly player: number) {
    super(`player ${player} has ${OPEN_ROOMS_PER_PLAYER} open rooms already`);
  }
}

/** Where a record comes from: a finished match, or a practice run. */
export type RecordSource = 'match' | 'practice';

/** How long an issued practice seed can be used (ms); older ones are deleted, used or not. */
export const PRACTICE_SEED_TTL_MS = 6 * 3600_000;
/** Unused seeds a player may hold; issuing another retires the oldest. */
export const PRACTICE_OPEN_SEEDS = 20;
/** Expired seeds are deleted at most this often (ms), when a seed is issued. */
export const SEED_SWEEP_MS = 10 * 60_000;

/** A practice seed as a submission finds it: issued and unused, used, or unknown (never issued to
 * this player for this kind, retired, or expired). */
export type PracticeSeedState = 'open' | 'used' | 'unknown';

/** Thrown by savePractice when its seed is not open; nothing is written. */
export class PracticeSeedError extends Error {
  constructor(readonly state: Exclude<PracticeSeedState, 'open'>) {
    super(`practice seed ${state}`);
  }
}

export interface BoardRow {
  readonly id: number;
  readonly name: string;
  readonly rating: number;
  readonly rd: number;
  readonly games: number;
  readonly wins: number;
}

export interface RecordEntry {
  readonly id: number;
  readonly kind: string;
  readonly what: string;
  readonly playerId: number;
  readonly name: string;
  readonly value: number;
  readonly matchId: number | null;
  readonly practiceId: number | null;
  readonly createdAt: number;
}

export interface MatchRow {
  readonly id: number;
  readonly kind: string;
  readonly raceTo: number;
  readonly player1: number;
  readonly name1: string;
  readonly player2: number;
  readonly name2: string;
  readonly startedAt: number;
  readonly finishedAt: number | null;
  readonly winner: number | null;
  readonly how: string | null;
  readonly rated: number | null;
  readonly unrated: UnratedReason | null;
}

/** A player found by their token, and when they were last seen (null before it was recorded). */
export type PlayerSeen = PlayerRow & { readonly lastSeen: number | null };

/** A finished match's result as stored: the scores parsed, `rated` a boolean. */
export interface StoredResult {
  readonly winner: number;
  readonly loser: number;
  readonly how: string;
  readonly scores: unknown;
  readonly rated: boolean;
  readonly unrated: UnratedReason | null;
}

/** One entry of a match's action log, parsed. */
export interface ActionRow {
  readonly seq: number;
  readonly action: unknown;
}

/** A player's rating of one kind (`name` empty: the caller knows whose). */
export type RatingRow = { readonly kind: string } & BoardRow;

/** One match with its starting game (JSON), for a replay. */
export type MatchDetail = MatchRow & { readonly start: string | null };

/** Which matches a page lists: a player's, a kind's, both or all. */
export interface MatchFilter {
  readonly player?: number;
  readonly kind?: string;
}

/** A verified practice run to save (see AsyncStore.savePractice). */
export interface PracticeRun {
  readonly player: number;
  readonly kind: string;
  readonly seed: number;
  readonly shots: string;
  readonly score: number;
  readonly records: readonly RecordRow[];
}
