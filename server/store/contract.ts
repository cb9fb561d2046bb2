// The store's contract: every read and write of the server's data, asynchronous, so that the
// embedded SQLite file (sqlite.ts) and a shared PostgreSQL (postgres.ts) serve it alike. All SQL
// lives behind it. What belongs together is one transaction in either: a move, its action, the
// result, the ratings and the records (saveChanges, startMatch); a practice run and its seed.
import type {
  ActionRow,
  BoardRow,
  IdlePage,
  MatchDetail,
  MatchFilter,
  MatchRow,
  NewMatch,
  NewRoom,
  PlayerRow,
  PlayerSeen,
  PracticeRun,
  PracticeSeedState,
  RatingRow,
  RecordEntry,
  RecordSource,
  RoomChange,
  RoomRow,
  StoredResult,
} from './types.ts';

export interface AsyncStore {
  /** Which database: 'sqlite' or 'postgres'. */
  readonly engine: 'sqlite' | 'postgres';

  // Players.
  /** The player with this token, and when they were last seen (null before it was recorded). */
  playerByTokenHash(hash: Buffer): Promise<PlayerSeen | undefined>;
  playerById(id: number): Promise<PlayerRow | undefined>;
  /** The id of another player whose name looks like this one (the same lower or upper key), if any. */
  nameOwner(name: string, exceptId?: number): Promise<number | undefined>;
  /** A new player; rejects on a name taken meanwhile (the unique name keys). */
  createPlayer(name: string, tokenHash: Buffer): Promise<PlayerRow>;
  /** The computer's player at a level, made on first use (once, however many ask at once). */
  computerPlayer(level: number, name: string, tokenHash: Buffer): Promise<PlayerRow>;
  /** A player's new name; rejects on a name taken meanwhile (the unique name keys). */
  renamePlayer(id: number, name: string): Promise<void>;
  /** Records that a player was here now. */
  touchPlayer(id: number): Promise<void>;
  /** Gives players from before the name keys theirs (see Store.fillNameKeys); returns how many. */
  fillNameKeys(): Promise<number>;
  /** Up to `limit` players with ids above `after`, and which may be deleted (idle since `cutoff`, referred to by nothing). */
  idlePlayers(after: number, cutoff: number, limit: number): Promise<IdlePage>;
  /** Deletes players in one transaction, skipping any a row still refers to; returns how many. */
  deletePlayers(ids: readonly number[]): Promise<number>;

  // Rooms and matches.
  /**
   * A new room; rejects with TooManyRoomsError, writing nothing, when its creator has
   * OPEN_ROOMS_PER_PLAYER rooms waiting or in play already (counted in the same transaction, so
   * the limit holds however many processes create at once).
   */
  createRoom(r: NewRoom): Promise<void>;
  /** Starts a match and returns its id. */
  createMatch(m: NewMatch): Promise<number>;
  /** Changes of rooms, their actions and any results (with ratings and records), in one transaction. */
  saveChanges(...changes: RoomChange[]): Promise<void>;
  /** A new match and the room's change that starts it, in one transaction; returns the match id. */
  startMatch(m: NewMatch, change: (matchId: number) => RoomChange): Promise<number>;
  /** Rooms not closed, oldest first: what a restart brings back. */
  openRooms(): Promise<RoomRow[]>;
  /** One room as last committed, closed or not: what a process taking the room over starts from. */
  room(id: string): Promise<RoomRow | undefined>;
  matchActions(matchId: number): Promise<ActionRow[]>;
  /** Shots each player has played in a match, from its log. */
  shotCounts(matchId: number): Promise<Map<string, number>>;
  /** When a match started (ms since the epoch, the server's clock). */
  matchStartedAt(matchId: number): Promise<number | undefined>;
  matchResult(matchId: number): Promise<StoredResult | undefined>;
  resultCount(): Promise<number>;

  // The HTTP API's reads.
  /** A page of a kind's leaderboard (established ratings only), best first, and how many it has. */
  leaderboard(kind: string, limit: number, offset: number): Promise<{ total: number; rows: BoardRow[] }>;
  ratingsOf(playerId: number): Promise<RatingRow[]>;
  /** A page of a kind's records from matches (the default) or from practice, best first. */
  records(kind: string, limit: number, offset: number, source?: RecordSource): Promise<RecordEntry[]>;
  /** A player's best record of each kind that has records. */
  bestRecordsOf(playerId: number): Promise<RecordEntry[]>;
  /** Matches newest first, of a player and of a kind when given. */
  matches(filter: MatchFilter, limit: number, offset: number): Promise<MatchRow[]>;
  match(id: number): Promise<MatchDetail | undefined>;

  // Practice.
  /** Issues a practice seed; resolves to the time issued, or null when the player holds that seed for that kind already. */
  issuePracticeSeed(player: number, kind: string, seed: number): Promise<number | null>;
  /** Deletes the seeds issued longer ago than PRACTICE_SEED_TTL_MS, used or not; returns how many. */
  sweepPracticeSeeds(): Promise<number>;
  practiceSeedState(player: number, kind: string, seed: number): Promise<PracticeSeedState>;
  /**
   * A verified practice run, in one transaction: its seed marked used (a PracticeSeedError, and
   * nothing written, unless open), the run, and each record that beats the player's standing one.
   */
  savePractice(run: PracticeRun): Promise<{ id: number; standing: boolean[] }>;

  // Operations.
  /** A real write, committed, waiting at most `waitMs` for a lock; rejects with what the database says. */
  probeWrite(waitMs: number): Promise<void>;
  /** The schema's version (the number of the last migration applied). */
  schemaVersion(): Promise<number>;
  /** Closes the database (the file, or the pool's connections). */
  close(): Promise<void>;
}
