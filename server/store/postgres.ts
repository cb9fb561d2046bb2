// The store on PostgreSQL (pg): the AsyncStore contract over a pool of connections, for many
// processes sharing one database. Each write that belongs together runs on one connection between
// BEGIN and COMMIT, and rolls back whole on any error. Where SQLite's single writer made a
// read-then-write safe (the ratings, the pair's daily limit, a player's practice record, the
// computer's player), a transaction-scoped advisory lock serialises the writers that share it.
import pg from 'pg';
import { migratePostgres, schemaVersionPostgres } from '../migrate-postgres.ts';
import { nameKeys } from '../players/names.ts';
import { NEW_RATING, type Rating } from '../ratings/glicko2.ts';
import { ANCHOR_BOARD_SIZE, DAY_MS, RATED_PER_PAIR_PER_DAY, rateResult, type UnratedReason } from '../ratings/policy.ts';
import type { AsyncStore } from './contract.ts';
import { SQL } from './postgres-sql.ts';
import {
  LEGACY_KEY,
  PRACTICE_OPEN_SEEDS,
  PRACTICE_SEED_TTL_MS,
  PracticeSeedError,
  SEED_SWEEP_MS,
  OPEN_ROOMS_PER_PLAYER,
  StaleRoomError,
  TooManyRoomsError,
  type ActionRow,
  type BoardRow,
  type IdlePage,
  type MatchDetail,
  type MatchFilter,
  type MatchResult,
  type MatchRow,
  type NewMatch,
  type NewRoom,
  type PlayerRow,
  type PlayerSeen,
  type PracticeRun,
  type PracticeSeedState,
  type RatingRow,
  type RecordEntry,
  type RecordSource,
  type RoomChange,
  type RoomRow,
  type StoredResult,
} from './types.ts';

/** A connection or the pool: anything that runs a statement. */
interface Queryable {
  query<R extends pg.QueryResultRow>(text: string, values?: unknown[]): Promise<pg.QueryResult<R>>;
}

const INT8_OID = 20;
/** BIGINT (ids, times in ms, counts) as numbers: every value the store keeps is below 2^53. */
const TYPES: pg.CustomTypesConfig = {
  getTypeParser: ((oid: number, format?: 'text' | 'binary') =>
    oid === INT8_OID && format !== 'binary' ? (v: string) => Number(v) : pg.types.getTypeParser(oid, format)) as pg.CustomTypesConfig['getTypeParser'],
};

/** First keys of the two-key advisory locks (the second is a player's id or a level). */
const LOCK_PLAYER = 1;
const LOCK_COMPUTER = 2;
const LOCK_NAME_KEYS = 3;
/** A player's rooms: their count against OPEN_ROOMS_PER_PLAYER and the new one's insert. */
const LOCK_ROOMS = 4;

/** PostgreSQL's error code for a foreign key violation. */
const FOREIGN_KEY_VIOLATION = '23503';

export interface PostgresOptions {
  /** Connections the pool may open (pg's default: 10). */
  readonly maxConnections?: number;
  /** How long to wait for a free connection before failing (ms). */
  readonly connectTimeoutMs?: number;
}

export class PostgresStore implements AsyncStore {
  readonly engine = 'postgres';
  private readonly pool: pg.Pool;
  /** When this process last deleted expired practice seeds. */
  private seedsSweptAt = -Infinity;

  constructor(
    url: string,
    private readonly now: () => number = Date.now,
    options: PostgresOptions = {},
  ) {
    this.pool = new pg.Pool({ connectionString: url, types: TYPES, max: options.maxConnections, connectionTimeoutMillis: options.connectTimeoutMs ?? 10_000 });
    // An idle connection the server drops is an event, not a crash: the pool replaces it.
    this.pool.on('error', (err) => console.error(`PostgreSQL: idle connection lost: ${err.message}`));
  }

  /**
   * Runs `fn` on a connection of its own. A connection lost meanwhile rejects the statement under
   * way; its 'error' event, which the pool listens to only while the connection is idle, is
   * handled here, or it would end the process. A connection that failed is closed, not reused.
   */
  private async withClient<T>(fn: (client: pg.PoolClient) => Promise<T>): Promise<T> {
    const client = await this.pool.connect();
    let lost: Error | undefined;
    const onError = (err: Error) => {
      lost = err;
    };
    client.on('error', onError);
    try {
      return await fn(client);
    } finally {
      client.removeListener('error', onError);
      client.release(lost);
    }
  }

  /** Runs `fn` in one transaction on one connection: committed if it resolves, rolled back if not. */
  private async tx<T>(fn: (q: Queryable) => Promise<T>): Promise<T> {
    return this.withClient(async (client) => {
      await client.query('BEGIN');
      try {
        const value = await fn(client);
        await client.query('COMMIT');
        return value;
      } catch (err) {
        // A rollback that fails too (the connection is gone) changes nothing: the server rolls back.
        await client.query('ROLLBACK').catch(() => undefined);
        throw err;
      }
    });
  }

  private async one<R extends pg.QueryResultRow>(q: Queryable, text: string, values: unknown[]): Promise<R | undefined> {
    return (await q.query<R>(text, values)).rows[0];
  }

  private async all<R extends pg.QueryResultRow>(q: Queryable, text: string, values: unknown[]): Promise<R[]> {
    return (await q.query<R>(text, values)).rows;
  }

  /** Holds, until the transaction ends, the locks of these players, in id order (no deadlock). */
  private async lockPlayers(q: Queryable, ...ids: number[]): Promise<void> {
    for (const id of [...new Set(ids)].sort((a, b) => a - b)) await q.query('SELECT pg_advisory_xact_lock($1, $2)', [LOCK_PLAYER, id | 0]);
  }

  async playerByTokenHash(hash: Buffer): Promise<PlayerSeen | undefined> {
    return this.one<PlayerSeen>(this.pool, SQL.playerByToken, [hash]);
  }

  async playerById(id: number): Promise<PlayerRow | undefined> {
    return this.one<PlayerRow>(this.pool, SQL.playerById, [id]);
  }

  async nameOwner(name: string, exceptId = 0): Promise<number | undefined> {
    const keys = nameKeys(name);
    return (await this.one<{ id: number }>(this.pool, SQL.nameOwner, [keys.lower, keys.upper, exceptId]))?.id;
  }

  async createPlayer(name: string, tokenHash: Buffer): Promise<PlayerRow> {
    return this.insertPlayer(this.pool, name, tokenHash);
  }

  private async insertPlayer(q: Queryable, name: string, tokenHash: Buffer): Promise<PlayerRow> {
    const keys = nameKeys(name);
    const now = this.now();
    const row = await this.one<{ id: number }>(q, SQL.insertPlayer, [name, keys.lower, keys.upper, tokenHash, now, now]);
    return { id: row!.id, name };
  }

  async computerPlayer(level: number, name: string, tokenHash: Buffer): Promise<PlayerRow> {
    return this.tx(async (q) => {
      await q.query('SELECT pg_advisory_xact_lock($1, $2)', [LOCK_COMPUTER, level]);
      const found = await this.one<PlayerRow>(q, SQL.computerByLevel, [level]);
      if (found) return found;
      const row = await this.insertPlayer(q, name, tokenHash);
      await q.query(SQL.insertComputer, [level, row.id]);
      return row;
    });
  }

  async renamePlayer(id: number, name: string): Promise<void> {
    const keys = nameKeys(name);
    await this.pool.query(SQL.renamePlayer, [name, keys.lower, keys.upper, id]);
  }

  async touchPlayer(id: number): Promise<void> {
    await this.pool.query(SQL.touchPlayer, [this.now(), id]);
  }

  /** As Store.fillNameKeys: the older player keeps a shared key, a later one gets LEGACY_KEY and its id. */
  async fillNameKeys(): Promise<number> {
    return this.tx(async (q) => {
      await q.query('SELECT pg_advisory_xact_lock($1, 0)', [LOCK_NAME_KEYS]);
      const rows = await this.all<PlayerRow>(q, SQL.keyless, []);
      for (const row of rows) {
        const keys = nameKeys(row.name);
        const lowerUsed = await this.one<{ id: number }>(q, SQL.keyLowerUsed, [keys.lower]);
        const upperUsed = await this.one<{ id: number }>(q, SQL.keyUpperUsed, [keys.upper]);
        const lower = lowerUsed && lowerUsed.id !== row.id ? `${LEGACY_KEY}${row.id}` : keys.lower;
        const upper = upperUsed && upperUsed.id !== row.id ? `${LEGACY_KEY}${row.id}` : keys.upper;
        await q.query(SQL.setKeys, [lower, upper, row.id]);
      }
      return rows.length;
    });
  }

  async idlePlayers(after: number, cutoff: number, limit: number): Promise<IdlePage> {
    const rows = await this.all<{ id: number; idle: boolean }>(this.pool, SQL.idlePage, [cutoff, after, limit]);
    return { idle: rows.filter((r) => r.idle).map((r) => r.id), next: rows.length < limit ? undefined : rows[rows.length - 1]!.id };
  }

  /** A player some row still refers to is skipped: its delete is undone to a savepoint, the rest stays. */
  async deletePlayers(ids: readonly number[]): Promise<number> {
    return this.tx(async (q) => {
      let deleted = 0;
      for (const id of ids) {
        await q.query('SAVEPOINT del');
        try {
          deleted += (await q.query(SQL.deletePlayer, [id])).rowCount ?? 0;
          await q.query('RELEASE SAVEPOINT del');
        } catch (err) {
          if ((err as { code?: string }).code !== FOREIGN_KEY_VIOLATION) throw err;
          await q.query('ROLLBACK TO SAVEPOINT del');
        }
      }
      return deleted;
    });
  }

  /** As Store.createRoom; the creator's lock makes the count and the insert one step across processes. */
  async createRoom(r: NewRoom): Promise<void> {
    await this.tx(async (q) => {
      await q.query('SELECT pg_advisory_xact_lock($1, $2)', [LOCK_ROOMS, r.createdBy | 0]);
      if ((await this.one<{ n: number }>(q, SQL.openRoomsOf, [r.createdBy]))!.n >= OPEN_ROOMS_PER_PLAYER) throw new TooManyRoomsError(r.createdBy);
      const now = this.now();
      await q.query(SQL.insertRoom, [r.id, r.kind, r.raceTo, r.private ? 1 : 0, r.shotClock, r.createdBy, now, r.status, r.state, now]);
    });
  }

  async createMatch(m: NewMatch): Promise<number> {
    return this.insertMatch(this.pool, m);
  }

  private async insertMatch(q: Queryable, m: NewMatch): Promise<number> {
    const row = await this.one<{ id: number }>(q, SQL.insertMatch, [m.roomId, m.kind, m.raceTo, m.player1, m.player2, m.seed, m.start, this.now()]);
    return row!.id;
  }

  async saveChanges(...changes: RoomChange[]): Promise<void> {
    const only = changes.length === 1 ? changes[0]! : undefined;
    if (only && !only.result) await this.move(only);
    else await this.tx((q) => this.applyChanges(q, changes));
  }

  /**
   * A room change with at most an action, the write of every shot: one statement, so one round
   * trip and its own transaction. A guarded action is inserted only when the room's row was, so a
   * stale room writes neither; an action refused (its place in the log taken) undoes the room's.
   */
  private async move(c: RoomChange): Promise<void> {
    const now = this.now();
    const expect = c.expectStateId ?? null;
    const written = c.action
      ? await this.pool.query(SQL.move, [c.status, c.state, now, c.roomId, expect, c.action.matchId, c.action.seq, c.action.json])
      : await this.pool.query(SQL.updateRoomIf, [c.status, c.state, now, c.roomId, expect]);
    if (c.expectStateId !== undefined && written.rowCount !== 1) throw new StaleRoomError(c.roomId, c.expectStateId);
  }

  private async applyChanges(q: Queryable, changes: readonly RoomChange[]): Promise<void> {
    // Every result's players locked first, all in one order: two saves never wait on each other in a circle.
    await this.lockPlayers(q, ...changes.flatMap((c) => (c.result ? [c.result.winner, c.result.loser] : [])));
    const now = this.now();
    for (const c of changes) {
      // The room's row first: a writer that waited for another's row lock then finds the stateId
      // moved on, and is refused before it tries its action (see RoomChange.expectStateId).
      if (c.expectStateId === undefined) await q.query(SQL.updateRoom, [c.status, c.state, now, c.roomId]);
      else if ((await q.query(SQL.updateRoomAt, [c.status, c.state, now, c.roomId, c.expectStateId])).rowCount !== 1) throw new StaleRoomError(c.roomId, c.expectStateId);
      if (c.action) await q.query(SQL.insertAction, [c.action.matchId, c.action.seq, c.action.json, now]);
      if (c.result) await this.finish(q, c.result, now);
    }
  }

  /**
   * A match's result, its ratings and its records, written once inside the caller's transaction
   * (see Store.finish). The two players' locks (taken by applyChanges) make the pair's daily limit
   * and each rating's read-then-write hold however results of other processes interleave.
   */
  private async finish(q: Queryable, r: MatchResult, now: number): Promise<void> {
    let unrated: UnratedReason | null = r.rated ? null : (r.unrated ?? 'few-shots');
    if ((await this.one<{ n: number }>(q, SQL.computersAmong, [r.winner, r.loser]))!.n > 0) unrated = 'computer';
    if (unrated === null && (await this.one<{ n: number }>(q, SQL.pairRated, [r.winner, r.loser, r.kind, now - DAY_MS]))!.n >= RATED_PER_PAIR_PER_DAY) unrated = 'pair-limit';
    const inserted = await q.query(SQL.insertResult, [r.matchId, r.winner, r.loser, r.how, r.scores, unrated === null ? 1 : 0, unrated, now]);
    if (inserted.rowCount !== 1) return;
    await q.query(SQL.finishMatch, [now, r.matchId]);
    if (unrated === null) {
      type Stored = Rating & { games: number; wins: number };
      const w = await this.one<Stored>(q, SQL.rating, [r.kind, r.winner]);
      const l = await this.one<Stored>(q, SQL.rating, [r.kind, r.loser]);
      const anchored = (await this.one<{ n: number }>(q, SQL.anchored, [r.kind, ANCHOR_BOARD_SIZE]))!.n >= ANCHOR_BOARD_SIZE;
      const next = rateResult(w ?? NEW_RATING, l ?? NEW_RATING, anchored);
      await q.query(SQL.upsertRating, [r.kind, r.winner, next.winner.rating, next.winner.rd, next.winner.vol, (w?.games ?? 0) + 1, (w?.wins ?? 0) + 1, now]);
      await q.query(SQL.upsertRating, [r.kind, r.loser, next.loser.rating, next.loser.rd, next.loser.vol, (l?.games ?? 0) + 1, l?.wins ?? 0, now]);
    }
    for (const rec of r.records) await q.query(SQL.insertRecord, [r.kind, rec.what, rec.player, rec.value, rec.better, r.matchId, now]);
  }

  async startMatch(m: NewMatch, change: (matchId: number) => RoomChange): Promise<number> {
    return this.tx(async (q) => {
      const id = await this.insertMatch(q, m);
      await this.applyChanges(q, [change(id)]);
      return id;
    });
  }

  async openRooms(): Promise<RoomRow[]> {
    return this.all<RoomRow>(this.pool, SQL.openRooms, []);
  }

  async room(id: string): Promise<RoomRow | undefined> {
    return this.one<RoomRow>(this.pool, SQL.room, [id]);
  }

  async matchActions(matchId: number): Promise<ActionRow[]> {
    const rows = await this.all<{ seq: number; action: string }>(this.pool, SQL.actions, [matchId]);
    return rows.map((r) => ({ seq: r.seq, action: JSON.parse(r.action) as unknown }));
  }

  async shotCounts(matchId: number): Promise<Map<string, number>> {
    const rows = await this.all<{ player: string | null; n: number }>(this.pool, SQL.shotCounts, [matchId]);
    return new Map(rows.map((r) => [String(r.player), r.n]));
  }

  async matchStartedAt(matchId: number): Promise<number | undefined> {
    return (await this.one<{ startedAt: number }>(this.pool, SQL.matchStart, [matchId]))?.startedAt;
  }

  async matchResult(matchId: number): Promise<StoredResult | undefined> {
    const r = await this.one<{ winner: number; loser: number; how: string; scores: string; rated: number; unrated: UnratedReason | null }>(this.pool, SQL.result, [matchId]);
    return r && { ...r, scores: JSON.parse(r.scores) as unknown, rated: r.rated === 1 };
  }

  async resultCount(): Promise<number> {
    return (await this.one<{ n: number }>(this.pool, SQL.resultCount, []))!.n;
  }

  /** Counted afresh each time: other processes change the ratings (SQLite's store caches it). */
  async leaderboard(kind: string, limit: number, offset: number): Promise<{ total: number; rows: BoardRow[] }> {
    const [count, rows] = await Promise.all([this.one<{ n: number }>(this.pool, SQL.boardCount, [kind]), this.all<BoardRow>(this.pool, SQL.board, [kind, limit, offset])]);
    return { total: count!.n, rows };
  }

  async ratingsOf(playerId: number): Promise<RatingRow[]> {
    return this.all<RatingRow>(this.pool, SQL.ratingsOf, [playerId]);
  }

  async records(kind: string, limit: number, offset: number, source: RecordSource = 'match'): Promise<RecordEntry[]> {
    return this.all<RecordEntry>(this.pool, source === 'practice' ? SQL.recordsPractice : SQL.recordsMatch, [kind, limit, offset]);
  }

  async bestRecordsOf(playerId: number): Promise<RecordEntry[]> {
    return this.all<RecordEntry>(this.pool, SQL.bestRecordsOf, [playerId]);
  }

  async matches(filter: MatchFilter, limit: number, offset: number): Promise<MatchRow[]> {
    if (filter.player !== undefined) return this.all<MatchRow>(this.pool, SQL.matchesPlayer, [filter.player, filter.kind ?? null, limit, offset]);
    if (filter.kind !== undefined) return this.all<MatchRow>(this.pool, SQL.matchesKind, [filter.kind, limit, offset]);
    return this.all<MatchRow>(this.pool, SQL.matchesAll, [limit, offset]);
  }

  async match(id: number): Promise<MatchDetail | undefined> {
    return this.one<MatchDetail>(this.pool, SQL.match, [id]);
  }

  async issuePracticeSeed(player: number, kind: string, seed: number): Promise<number | null> {
    return this.tx(async (q) => {
      const now = this.now();
      if (now - this.seedsSweptAt >= SEED_SWEEP_MS) await this.sweep(q, now);
      if ((await q.query(SQL.issueSeed, [player, kind, seed, now])).rowCount !== 1) return null;
      await q.query(SQL.retireSeeds, [player, now - PRACTICE_SEED_TTL_MS, PRACTICE_OPEN_SEEDS]);
      return now;
    });
  }

  async sweepPracticeSeeds(): Promise<number> {
    return this.sweep(this.pool, this.now());
  }

  private async sweep(q: Queryable, now: number): Promise<number> {
    this.seedsSweptAt = now;
    return (await q.query(SQL.sweepSeeds, [now - PRACTICE_SEED_TTL_MS])).rowCount ?? 0;
  }

  async practiceSeedState(player: number, kind: string, seed: number): Promise<PracticeSeedState> {
    return this.seedState(this.pool, player, kind, seed);
  }

  private async seedState(q: Queryable, player: number, kind: string, seed: number): Promise<PracticeSeedState> {
    const row = await this.one<{ issuedAt: number; usedAt: number | null }>(q, SQL.seed, [player, kind, seed]);
    if (!row || row.issuedAt < this.now() - PRACTICE_SEED_TTL_MS) return 'unknown';
    return row.usedAt === null ? 'open' : 'used';
  }

  /** As Store.savePractice; the player's lock keeps two of their runs from racing for one standing record. */
  async savePractice(run: PracticeRun): Promise<{ id: number; standing: boolean[] }> {
    return this.tx(async (q) => {
      const now = this.now();
      await this.lockPlayers(q, run.player);
      if ((await q.query(SQL.useSeed, [now, run.player, run.kind, run.seed, now - PRACTICE_SEED_TTL_MS])).rowCount !== 1) {
        throw new PracticeSeedError((await this.seedState(q, run.player, run.kind, run.seed)) === 'used' ? 'used' : 'unknown');
      }
      const id = (await this.one<{ id: number }>(q, SQL.insertPractice, [run.player, run.kind, run.seed, run.shots, run.score, now]))!.id;
      const standing: boolean[] = [];
      for (const rec of run.records) {
        await q.query(SQL.dropWorsePractice, [rec.player, run.kind, rec.what, rec.better]);
        standing.push((await q.query(SQL.insertPracticeRecord, [run.kind, rec.what, rec.player, rec.value, rec.better, id, now])).rowCount === 1);
      }
      return { id, standing };
    });
  }

  /** A real write, committed; a lock held elsewhere fails it after `waitMs` (lock_timeout; 0 there would mean forever). */
  async probeWrite(waitMs: number): Promise<void> {
    await this.tx(async (q) => {
      await q.query(`SET LOCAL lock_timeout = ${Math.max(1, Math.floor(waitMs))}`);
      await q.query(SQL.probeWrite, [this.now()]);
    });
  }

  /** Applies PostgreSQL's migrations from `dir` (see migratePostgres); returns the files applied. */
  async migrate(dir: string): Promise<string[]> {
    return this.withClient((client) => migratePostgres(client, dir));
  }

  async schemaVersion(): Promise<number> {
    return this.withClient((client) => schemaVersionPostgres(client));
  }

  async close(): Promise<void> {
    if (!this.pool.ended) await this.pool.end();
  }
}
