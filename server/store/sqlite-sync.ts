// Every SQL statement of the embedded server, synchronous over better-sqlite3: players, rooms,
// matches with their action logs, results. Each write that belongs together is one transaction,
// so a crash leaves either all of it or none. SqliteStore (sqlite.ts) serves it as an AsyncStore.
import type { Database } from 'better-sqlite3';
import { nameKeys } from '../players/names.ts';
import { NEW_RATING, PROVISIONAL_RD, type Rating } from '../ratings/glicko2.ts';
import { ANCHOR_BOARD_SIZE, DAY_MS, RATED_PER_PAIR_PER_DAY, rateResult, type UnratedReason } from '../ratings/policy.ts';
import {
  LEGACY_KEY,
  PRACTICE_OPEN_SEEDS,
  PRACTICE_SEED_TTL_MS,
  PracticeSeedError,
  SEED_SWEEP_MS,
  OPEN_ROOMS_PER_PLAYER,
  StaleRoomError,
  TooManyRoomsError,
  type BoardRow,
  type IdlePage,
  type MatchResult,
  type MatchRow,
  type NewMatch,
  type NewRoom,
  type PlayerRow,
  type PracticeSeedState,
  type RecordEntry,
  type RecordRow,
  type RecordSource,
  type RoomChange,
  type RoomRow,
} from './types.ts';

const MATCH_COLUMNS = `m.id, m.kind, m.race_to AS raceTo, m.player1, p1.name AS name1, m.player2, p2.name AS name2,
  m.started_at AS startedAt, m.finished_at AS finishedAt, r.winner, r.how, r.rated, r.unrated
  FROM matches m JOIN players p1 ON p1.id = m.player1 JOIN players p2 ON p2.id = m.player2 LEFT JOIN results r ON r.match_id = m.id`;

const RECORD_COLUMNS = `rec.id, rec.kind, rec.what, rec.player_id AS playerId, p.name, rec.value, rec.match_id AS matchId,
  rec.practice_id AS practiceId, rec.created_at AS createdAt FROM records rec JOIN players p ON p.id = rec.player_id`;

/**
 * Established (not provisional) ratings: the leaderboard's, read through the partial index
 * ratings_board (migrations/008). INDEXED BY makes a bound that disagrees with the index's fail
 * when the statements are prepared, instead of quietly reading the whole table.
 */
const ESTABLISHED = `rd < ${PROVISIONAL_RD}`;
const BOARD = 'INDEXED BY ratings_board';

export class Store {
  private readonly s;
  /** When expired practice seeds were last deleted. */
  private seedsSweptAt = -Infinity;
  /** Players on the leaderboard per kind, counted once and forgotten when a rating changes. */
  private readonly boardCount = new Map<string, number>();
  /** The computer's players (migration 010). */
  private readonly computer;

  constructor(
    private readonly db: Database,
    private readonly now: () => number = Date.now,
  ) {
    this.s = {
      playerByToken: db.prepare<[Buffer], PlayerRow & { lastSeen: number | null }>('SELECT id, name, last_seen AS lastSeen FROM players WHERE token_hash = ?'),
      playerById: db.prepare<[number], PlayerRow>('SELECT id, name FROM players WHERE id = ?'),
      nameOwner: db.prepare<[string, string, number], { id: number }>('SELECT id FROM players WHERE (name_key_lower = ? OR name_key_upper = ?) AND id <> ? LIMIT 1'),
      insertPlayer: db.prepare<[string, string, string, Buffer, number, number]>(
        'INSERT INTO players (name, name_key_lower, name_key_upper, token_hash, created_at, last_seen) VALUES (?, ?, ?, ?, ?, ?)',
      ),
      renamePlayer: db.prepare<[string, string, string, number]>('UPDATE players SET name = ?, name_key_lower = ?, name_key_upper = ? WHERE id = ?'),
      touchPlayer: db.prepare<[number, number]>('UPDATE players SET last_seen = ? WHERE id = ?'),
      keyless: db.prepare<[], PlayerRow>('SELECT id, name FROM players WHERE name_key_lower IS NULL OR name_key_upper IS NULL ORDER BY id'),
      keyLowerUsed: db.prepare<[string], { id: number }>('SELECT id FROM players WHERE name_key_lower = ?'),
      keyUpperUsed: db.prepare<[string], { id: number }>('SELECT id FROM players WHERE name_key_upper = ?'),
      setKeys: db.prepare<[string, string, number]>('UPDATE players SET name_key_lower = ?, name_key_upper = ? WHERE id = ?'),
      // A page of players by id, each marked idle when not seen since the cutoff and referred to by
      // no row anywhere; every subquery walks an index on the referring column.
      idlePage: db.prepare<[number, number, number], { id: number; idle: number }>(
        `SELECT p.id, (coalesce(p.last_seen, p.created_at) < ?
           AND NOT EXISTS (SELECT 1 FROM matches WHERE player1 = p.id)
           AND NOT EXISTS (SELECT 1 FROM matches WHERE player2 = p.id)
           AND NOT EXISTS (SELECT 1 FROM rooms WHERE created_by = p.id)
           AND NOT EXISTS (SELECT 1 FROM ratings WHERE player_id = p.id)
           AND NOT EXISTS (SELECT 1 FROM records WHERE player_id = p.id)
           AND NOT EXISTS (SELECT 1 FROM practice_runs WHERE player_id = p.id)
           AND NOT EXISTS (SELECT 1 FROM practice_seeds WHERE player_id = p.id)) AS idle
         FROM players p WHERE p.id > ? ORDER BY p.id LIMIT ?`,
      ),
      deletePlayer: db.prepare<[number]>('DELETE FROM players WHERE id = ?'),
      insertRoom: db.prepare<[string, string, number, number, number, number, number, string, string, number]>(
        'INSERT INTO rooms (id, kind, race_to, private, shot_clock, created_by, created_at, status, state, updated_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)',
      ),
      openRoomsOf: db.prepare<[number], { n: number }>("SELECT COUNT(*) AS n FROM rooms WHERE created_by = ? AND status IN ('waiting', 'playing')"),
      updateRoom: db.prepare<[string, string, number, string]>('UPDATE rooms SET status = ?, state = ?, updated_at = ? WHERE id = ?'),
      updateRoomAt: db.prepare<[string, string, number, string, number]>(
        "UPDATE rooms SET status = ?, state = ?, updated_at = ? WHERE id = ? AND json_extract(state, '$.stateId') = ?",
      ),
      room: db.prepare<[string], RoomRow>('SELECT id, status, state FROM rooms WHERE id = ?'),
      openRooms: db.prepare<[], RoomRow>("SELECT id, status, state FROM rooms WHERE status IN ('waiting', 'playing', 'over') ORDER BY created_at, id"),
      insertMatch: db.prepare<[string, string, number, number, number, number, string, number]>(
        'INSERT INTO matches (room_id, kind, race_to, player1, player2, seed, start, started_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)',
      ),
      insertAction: db.prepare<[number, number, string, number]>('INSERT INTO match_actions (match_id, seq, action, created_at) VALUES (?, ?, ?, ?)'),
      actions: db.prepare<[number], { seq: number; action: string }>('SELECT seq, action FROM match_actions WHERE match_id = ? ORDER BY seq'),
      shotCounts: db.prepare<[number], { player: string; n: number }>(
        `SELECT json_extract(action, '$.player') AS player, count(*) AS n FROM match_actions
         WHERE match_id = ? AND json_extract(action, '$.type') = 'shot' GROUP BY 1`,
      ),
      insertResult: db.prepare<[number, number, number, string, string, number, string | null, number]>(
        'INSERT OR IGNORE INTO results (match_id, winner, loser, how, scores, rated, unrated, finished_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)',
      ),
      matchStart: db.prepare<[number], { startedAt: number }>('SELECT started_at AS startedAt FROM matches WHERE id = ?'),
      // Rated results of a kind between two players since a time: two seeks of results_pair, then
      // each match found looked up for its kind (the daily limit keeps them few).
      pairRated: db.prepare<[{ a: number; b: number; kind: string; since: number }], { n: number }>(
        `SELECT count(*) AS n FROM matches WHERE kind = @kind AND id IN (
           SELECT match_id FROM results WHERE rated = 1 AND winner = @a AND loser = @b AND finished_at > @since
           UNION ALL SELECT match_id FROM results WHERE rated = 1 AND winner = @b AND loser = @a AND finished_at > @since)`,
      ),
      // Whether a kind's board holds ANCHOR_BOARD_SIZE players: at most that many index entries read.
      anchored: db.prepare<[string, number], { n: number }>(`SELECT count(*) AS n FROM (SELECT 1 FROM ratings ${BOARD} WHERE kind = ? AND ${ESTABLISHED} LIMIT ?)`),
      rating: db.prepare<[string, number], Rating & { games: number; wins: number }>('SELECT rating, rd, vol, games, wins FROM ratings WHERE kind = ? AND player_id = ?'),
      upsertRating: db.prepare<[string, number, number, number, number, number, number, number]>(
        `INSERT INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)
         ON CONFLICT (kind, player_id) DO UPDATE SET rating = excluded.rating, rd = excluded.rd, vol = excluded.vol,
           games = excluded.games, wins = excluded.wins, updated_at = excluded.updated_at`,
      ),
      insertRecord: db.prepare<[string, string, number, number, number, number | null, number | null, number]>(
        'INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?)',
      ),
      finishMatch: db.prepare<[number, number]>('UPDATE matches SET finished_at = ? WHERE id = ? AND finished_at IS NULL'),
      result: db.prepare<[number], { winner: number; loser: number; how: string; scores: string; rated: number; unrated: UnratedReason | null }>(
        'SELECT winner, loser, how, scores, rated, unrated FROM results WHERE match_id = ?',
      ),
      resultCount: db.prepare<[], { n: number }>('SELECT count(*) AS n FROM results'),
      // The page is cut from the covering partial index ratings_board first, so that an OFFSET
      // skips index entries only, not a rating row and a player row for each place skipped, and
      // provisional ratings are not there to skip.
      board: db.prepare<[string, number, number], BoardRow>(
        `SELECT r.player_id AS id, p.name, r.rating, r.rd, r.games, r.wins
         FROM (SELECT kind, player_id FROM ratings ${BOARD} WHERE kind = ? AND ${ESTABLISHED} ORDER BY rating DESC, player_id LIMIT ? OFFSET ?) page
         JOIN ratings r ON r.kind = page.kind AND r.player_id = page.player_id JOIN players p ON p.id = r.player_id
         ORDER BY r.rating DESC, r.player_id`,
      ),
      boardCount: db.prepare<[string], { n: number }>(`SELECT count(*) AS n FROM ratings ${BOARD} WHERE kind = ? AND ${ESTABLISHED}`),
      ratingsOf: db.prepare<[number], { kind: string } & BoardRow>(
        'SELECT kind, player_id AS id, \'\' AS name, rating, rd, games, wins FROM ratings WHERE player_id = ? ORDER BY kind',
      ),
      // Likewise: the page's ids from the covering index of its board (records_board_match or
      // records_board_practice), then their rows.
      recordsMatch: db.prepare<[string, number, number], RecordEntry>(
        `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (SELECT id FROM records WHERE kind = ? AND match_id IS NOT NULL ORDER BY better DESC, id LIMIT ? OFFSET ?)
         ORDER BY rec.better DESC, rec.id`,
      ),
      recordsPractice: db.prepare<[string, number, number], RecordEntry>(
        `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (SELECT id FROM records WHERE kind = ? AND practice_id IS NOT NULL ORDER BY better DESC, id LIMIT ? OFFSET ?)
         ORDER BY rec.better DESC, rec.id`,
      ),
      // A player's best record of each kind: the first row of each kind in records_player_best.
      bestRecordsOf: db.prepare<[number, number], RecordEntry>(
        `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (
           SELECT (SELECT id FROM records r WHERE r.player_id = ? AND r.kind = k.kind ORDER BY r.better DESC, r.id LIMIT 1)
           FROM (SELECT 'nineball' AS kind UNION ALL SELECT 'snooker' UNION ALL SELECT 'threecushion') k)
         AND rec.player_id = ? ORDER BY rec.kind`,
      ),
      matchesAll: db.prepare<[number, number], MatchRow>(`SELECT ${MATCH_COLUMNS} ORDER BY m.id DESC LIMIT ? OFFSET ?`),
      matchesKind: db.prepare<[string, number, number], MatchRow>(`SELECT ${MATCH_COLUMNS} WHERE m.kind = ? ORDER BY m.id DESC LIMIT ? OFFSET ?`),
      // The page's ids by a merge of matches_player1 and matches_player2, both walked newest first,
      // which stops once the page is full: a player's thousands of matches are not all read.
      matchesPlayer: db.prepare<[{ player: number; kind: string | null; limit: number; offset: number }], MatchRow>(
        `SELECT ${MATCH_COLUMNS} WHERE m.id IN (
           SELECT id FROM matches WHERE player1 = @player AND (@kind IS NULL OR kind = @kind)
           UNION SELECT id FROM matches WHERE player2 = @player AND (@kind IS NULL OR kind = @kind)
           ORDER BY id DESC LIMIT @limit OFFSET @offset)
         ORDER BY m.id DESC`,
      ),
      match: db.prepare<[number], MatchRow & { start: string | null }>(`SELECT ${MATCH_COLUMNS.replace('m.id,', 'm.id, m.start,')} WHERE m.id = ?`),
      insertPractice: db.prepare<[number, string, number, string, number, number]>(
        'INSERT INTO practice_runs (player_id, kind, seed, shots, score, created_at) VALUES (?, ?, ?, ?, ?, ?)',
      ),
      issueSeed: db.prepare<[number, string, number, number]>(
        'INSERT INTO practice_seeds (player_id, kind, seed, issued_at) VALUES (?, ?, ?, ?) ON CONFLICT (player_id, kind, seed) DO NOTHING',
      ),
      retireSeeds: db.prepare<[number, number, number]>(
        `DELETE FROM practice_seeds WHERE id IN (
           SELECT id FROM practice_seeds WHERE player_id = ? AND used_at IS NULL AND issued_at >= ? ORDER BY id DESC LIMIT -1 OFFSET ?)`,
      ),
      sweepSeeds: db.prepare<[number]>('DELETE FROM practice_seeds WHERE issued_at < ?'),
      seed: db.prepare<[number, string, number], { issuedAt: number; usedAt: number | null }>(
        'SELECT issued_at AS issuedAt, used_at AS usedAt FROM practice_seeds WHERE player_id = ? AND kind = ? AND seed = ?',
      ),
      useSeed: db.prepare<[number, number, string, number, number]>(
        'UPDATE practice_seeds SET used_at = ? WHERE player_id = ? AND kind = ? AND seed = ? AND used_at IS NULL AND issued_at >= ?',
      ),
      // A practice record stands alone per player, kind and type: a better one replaces it (a new
      // row, so that ties rank by who got there first), a worse or equal one is not kept.
      dropWorsePractice: db.prepare<[number, string, string, number]>(
        'DELETE FROM records WHERE practice_id IS NOT NULL AND player_id = ? AND kind = ? AND what = ? AND better < ?',
      ),
      insertPracticeRecord: db.prepare<[string, string, number, number, number, number, number]>(
        `INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES (?, ?, ?, ?, ?, NULL, ?, ?)
         ON CONFLICT (player_id, kind, what) WHERE practice_id IS NOT NULL DO NOTHING`,
      ),
    };
    // Prepared only on a schema that has them (bench/store-fill.ts opens older ones).
    const hasComputers = db.prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'computers'").get() !== undefined;
    this.computer = hasComputers
      ? {
          byLevel: db.prepare<[number], PlayerRow>('SELECT p.id, p.name FROM computers c JOIN players p ON p.id = c.player_id WHERE c.level = ?'),
          insert: db.prepare<[number, number]>('INSERT INTO computers (level, player_id) VALUES (?, ?)'),
          among: db.prepare<[number, number], { n: number }>('SELECT count(*) AS n FROM computers WHERE player_id IN (?, ?)'),
        }
      : undefined;
    this.fillNameKeys();
  }

  /** The player with this token, and when they were last seen (null before it was recorded). */
  playerByTokenHash(hash: Buffer): (PlayerRow & { lastSeen: number | null }) | undefined {
    return this.s.playerByToken.get(hash);
  }

  playerById(id: number): PlayerRow | undefined {
    return this.s.playerById.get(id);
  }

  /** The id of another player whose name looks like this one (the same lower or upper key), if any. */
  nameOwner(name: string, exceptId = 0): number | undefined {
    const keys = nameKeys(name);
    return this.s.nameOwner.get(keys.lower, keys.upper, exceptId)?.id;
  }

  /** A new player; throws on a name taken meanwhile (the UNIQUE constraints). */
  createPlayer(name: string, tokenHash: Buffer): PlayerRow {
    const keys = nameKeys(name);
    const now = this.now();
    const info = this.s.insertPlayer.run(name, keys.lower, keys.upper, tokenHash, now, now);
    return { id: Number(info.lastInsertRowid), name };
  }

  /**
   * The computer's player at a level (server/computer/player.ts names it), made on first use: a
   * stored player so that its matches are recorded, with a token nobody holds.
   */
  computerPlayer(level: number, name: string, tokenHash: Buffer): PlayerRow {
    const c = this.computer;
    if (!c) throw new Error('the database has no computers table (migration 010)');
    return this.db.transaction(() => {
      const found = c.byLevel.get(level);
      if (found) return found;
      const row = this.createPlayer(name, tokenHash);
      c.insert.run(level, row.id);
      return row;
    })();
  }

  /** A player's new name; throws on a name taken meanwhile (the UNIQUE constraints). */
  renamePlayer(id: number, name: string): void {
    const keys = nameKeys(name);
    this.s.renamePlayer.run(name, keys.lower, keys.upper, id);
  }

  /** Records that a player was here now. */
  touchPlayer(id: number): void {
    this.s.touchPlayer.run(this.now(), id);
  }

  /**
   * Gives players from before the name keys theirs, oldest first, in one transaction. Names taken
   * then were unique only without regard to ASCII case, so two may share a key now: the older
   * player keeps the plain key, a later one gets "\u0001" and its id instead, which no real name's
   * key can equal (names never hold control characters) and which stays unique. That player keeps
   * their name; a lookalike of it stays taken by the older one.
   */
  fillNameKeys(): number {
    return this.db.transaction(() => {
      const rows = this.s.keyless.all();
      for (const row of rows) {
        const keys = nameKeys(row.name);
        const lowerUsed = this.s.keyLowerUsed.get(keys.lower);
        const upperUsed = this.s.keyUpperUsed.get(keys.upper);
        const lower = lowerUsed && lowerUsed.id !== row.id ? `${LEGACY_KEY}${row.id}` : keys.lower;
        const upper = upperUsed && upperUsed.id !== row.id ? `${LEGACY_KEY}${row.id}` : keys.upper;
        this.s.setKeys.run(lower, upper, row.id);
      }
      return rows.length;
    })();
  }

  /**
   * Up to `limit` players with ids above `after`, and which of them may be deleted: not seen since
   * `cutoff` and referred to by nothing (no match, room, rating, record or practice run).
   */
  idlePlayers(after: number, cutoff: number, limit: number): IdlePage {
    const rows = this.s.idlePage.all(cutoff, after, limit);
    return { idle: rows.filter((r) => r.idle === 1).map((r) => r.id), next: rows.length < limit ? undefined : rows[rows.length - 1]!.id };
  }

  /**
   * Deletes players in one transaction; returns how many. A player some row still refers to (a
   * table the pruner's query does not know) is kept: the foreign key refuses, and that one is skipped.
   */
  deletePlayers(ids: readonly number[]): number {
    return this.db.transaction(() => {
      let deleted = 0;
      for (const id of ids) {
        try {
          deleted += this.s.deletePlayer.run(id).changes;
        } catch (err) {
          if ((err as { code?: string }).code !== 'SQLITE_CONSTRAINT_FOREIGNKEY') throw err;
        }
      }
      return deleted;
    })();
  }

  /** A new room, unless its creator has OPEN_ROOMS_PER_PLAYER open already (TooManyRoomsError): counted and written in one write transaction. */
  createRoom(r: NewRoom): void {
    this.db
      .transaction(() => {
        if (this.s.openRoomsOf.get(r.createdBy)!.n >= OPEN_ROOMS_PER_PLAYER) throw new TooManyRoomsError(r.createdBy);
        const now = this.now();
        this.s.insertRoom.run(r.id, r.kind, r.raceTo, r.private ? 1 : 0, r.shotClock, r.createdBy, now, r.status, r.state, now);
      })
      .immediate();
  }

  /** Starts a match and returns its id. */
  createMatch(m: NewMatch): number {
    const info = this.s.insertMatch.run(m.roomId, m.kind, m.raceTo, m.player1, m.player2, m.seed, m.start, this.now());
    return Number(info.lastInsertRowid);
  }

  /**
   * Changes of rooms, their actions and any results, in one transaction. A room not at the
   * stateId its change expects refuses the whole save (StaleRoomError); its row is written first,
   * so that the refusal comes before any action or result is tried.
   */
  saveChanges(...changes: RoomChange[]): void {
    this.db.transaction(() => {
      const now = this.now();
      for (const c of changes) {
        if (c.expectStateId === undefined) this.s.updateRoom.run(c.status, c.state, now, c.roomId);
        else if (this.s.updateRoomAt.run(c.status, c.state, now, c.roomId, c.expectStateId).changes !== 1) throw new StaleRoomError(c.roomId, c.expectStateId);
        if (c.action) this.s.insertAction.run(c.action.matchId, c.action.seq, c.action.json, now);
        if (c.result) this.finish(c.result, now);
      }
    })();
  }

  /**
   * A match's result, its ratings and its records: written once, inside the caller's transaction.
   * A retried finish finds the result there and adds nothing. The pair's daily limit is decided
   * here, in the transaction that writes the result, so that it holds however results interleave.
   */
  private finish(r: MatchResult, now: number): void {
    let unrated = r.rated ? null : (r.unrated ?? 'few-shots');
    // A match against the computer is never rated, whatever the service said.
    if (this.computer && this.computer.among.get(r.winner, r.loser)!.n > 0) unrated = 'computer';
    if (unrated === null && this.s.pairRated.get({ a: r.winner, b: r.loser, kind: r.kind, since: now - DAY_MS })!.n >= RATED_PER_PAIR_PER_DAY) unrated = 'pair-limit';
    const inserted = this.s.insertResult.run(r.matchId, r.winner, r.loser, r.how, r.scores, unrated === null ? 1 : 0, unrated, now).changes === 1;
    if (!inserted) return;
    this.s.finishMatch.run(now, r.matchId);
    if (unrated === null) {
      const w = this.s.rating.get(r.kind, r.winner);
      const l = this.s.rating.get(r.kind, r.loser);
      const anchored = this.s.anchored.get(r.kind, ANCHOR_BOARD_SIZE)!.n >= ANCHOR_BOARD_SIZE;
      const next = rateResult(w ?? NEW_RATING, l ?? NEW_RATING, anchored);
      this.s.upsertRating.run(r.kind, r.winner, next.winner.rating, next.winner.rd, next.winner.vol, (w?.games ?? 0) + 1, (w?.wins ?? 0) + 1, now);
      this.s.upsertRating.run(r.kind, r.loser, next.loser.rating, next.loser.rd, next.loser.vol, (l?.games ?? 0) + 1, l?.wins ?? 0, now);
      this.boardCount.delete(r.kind);
    }
    for (const rec of r.records) this.s.insertRecord.run(r.kind, rec.what, rec.player, rec.value, rec.better, r.matchId, null, now);
  }

  /** A new match and the room's change that starts it, in one transaction; returns the match id. */
  startMatch(m: NewMatch, change: (matchId: number) => RoomChange): number {
    return this.db.transaction(() => {
      const id = this.createMatch(m);
      this.saveChanges(change(id));
      return id;
    })();
  }

  /** Rooms not closed, oldest first: what a restart brings back. */
  openRooms(): RoomRow[] {
    return this.s.openRooms.all();
  }

  /** One room as last committed, closed or not. */
  room(id: string): RoomRow | undefined {
    return this.s.room.get(id);
  }

  matchActions(matchId: number): { seq: number; action: unknown }[] {
    return this.s.actions.all(matchId).map((r) => ({ seq: r.seq, action: JSON.parse(r.action) as unknown }));
  }

  /** Shots each player has played in a match, from its log. */
  shotCounts(matchId: number): Map<string, number> {
    return new Map(this.s.shotCounts.all(matchId).map((r) => [String(r.player), r.n]));
  }

  /** When a match started (ms since the epoch, the server's clock). */
  matchStartedAt(matchId: number): number | undefined {
    return this.s.matchStart.get(matchId)?.startedAt;
  }

  matchResult(matchId: number): { winner: number; loser: number; how: string; scores: unknown; rated: boolean; unrated: UnratedReason | null } | undefined {
    const r = this.s.result.get(matchId);
    return r && { ...r, scores: JSON.parse(r.scores) as unknown, rated: r.rated === 1 };
  }

  /**
   * A page of the leaderboard of a kind, best first, and how many players it has: established
   * ratings only (RD under PROVISIONAL_RD), ranked among themselves.
   */
  leaderboard(kind: string, limit: number, offset: number): { total: number; rows: BoardRow[] } {
    let total = this.boardCount.get(kind);
    if (total === undefined) {
      total = this.s.boardCount.get(kind)!.n;
      this.boardCount.set(kind, total);
    }
    return { total, rows: this.s.board.all(kind, limit, offset) };
  }

  ratingsOf(playerId: number): ({ kind: string } & BoardRow)[] {
    return this.s.ratingsOf.all(playerId);
  }

  /** A page of a kind's records from matches (the default) or from practice, best first. */
  records(kind: string, limit: number, offset: number, source: RecordSource = 'match'): RecordEntry[] {
    return (source === 'practice' ? this.s.recordsPractice : this.s.recordsMatch).all(kind, limit, offset);
  }

  /** A player's best record of each kind that has records. */
  bestRecordsOf(playerId: number): RecordEntry[] {
    return this.s.bestRecordsOf.all(playerId, playerId);
  }

  /** Matches newest first, of a player and of a kind when given. */
  matches(filter: { player?: number; kind?: string }, limit: number, offset: number): MatchRow[] {
    if (filter.player !== undefined) return this.s.matchesPlayer.all({ player: filter.player, kind: filter.kind ?? null, limit, offset });
    if (filter.kind !== undefined) return this.s.matchesKind.all(filter.kind, limit, offset);
    return this.s.matchesAll.all(limit, offset);
  }

  match(id: number): (MatchRow & { start: string | null }) | undefined {
    return this.s.match.get(id);
  }

  /**
   * Issues a practice seed to a player for a kind and returns the time issued; null when that
   * player already holds that seed for that kind (draw another). Retires the player's oldest unused seeds beyond
   * PRACTICE_OPEN_SEEDS, and now and then deletes the expired ones of everyone.
   */
  issuePracticeSeed(player: number, kind: string, seed: number): number | null {
    return this.db.transaction(() => {
      const now = this.now();
      if (now - this.seedsSweptAt >= SEED_SWEEP_MS) this.sweepPracticeSeeds();
      if (this.s.issueSeed.run(player, kind, seed, now).changes !== 1) return null;
      this.s.retireSeeds.run(player, now - PRACTICE_SEED_TTL_MS, PRACTICE_OPEN_SEEDS);
      return now;
    })();
  }

  /** Deletes the seeds issued longer ago than PRACTICE_SEED_TTL_MS, used or not; returns how many. */
  sweepPracticeSeeds(): number {
    const now = this.now();
    this.seedsSweptAt = now;
    return this.s.sweepSeeds.run(now - PRACTICE_SEED_TTL_MS).changes;
  }

  practiceSeedState(player: number, kind: string, seed: number): PracticeSeedState {
    const row = this.s.seed.get(player, kind, seed);
    if (!row || row.issuedAt < this.now() - PRACTICE_SEED_TTL_MS) return 'unknown';
    return row.usedAt === null ? 'open' : 'used';
  }

  /**
   * A verified practice run, in one transaction: its seed marked used (a PracticeSeedError, and
   * nothing written, unless the seed is open), the run, and each record that beats the player's
   * standing practice record of its kind and type (which it replaces). Returns the run's id and,
   * for each record, whether it now stands.
   */
  savePractice(run: { player: number; kind: string; seed: number; shots: string; score: number; records: readonly RecordRow[] }): { id: number; standing: boolean[] } {
    return this.db.transaction(() => {
      const now = this.now();
      if (this.s.useSeed.run(now, run.player, run.kind, run.seed, now - PRACTICE_SEED_TTL_MS).changes !== 1) {
        throw new PracticeSeedError(this.practiceSeedState(run.player, run.kind, run.seed) === 'used' ? 'used' : 'unknown');
      }
      const id = Number(this.s.insertPractice.run(run.player, run.kind, run.seed, run.shots, run.score, now).lastInsertRowid);
      const standing = run.records.map((rec) => {
        this.s.dropWorsePractice.run(rec.player, run.kind, rec.what, rec.better);
        return this.s.insertPracticeRecord.run(run.kind, rec.what, rec.player, rec.value, rec.better, id, now).changes === 1;
      });
      return { id, standing };
    })();
  }

  resultCount(): number {
    return this.s.resultCount.get()!.n;
  }

  /**
   * A real write (one row rewritten and committed), so that a full disk, a read-only file or a lock
   * held elsewhere shows; waits at most `waitMs` for a lock. Throws what SQLite says.
   */
  probeWrite(waitMs: number): void {
    const busy = this.db.pragma('busy_timeout', { simple: true }) as number;
    this.db.pragma(`busy_timeout = ${Math.max(0, Math.floor(waitMs))}`);
    try {
      this.db.prepare('INSERT INTO health (id, checked_at) VALUES (1, ?) ON CONFLICT (id) DO UPDATE SET checked_at = excluded.checked_at').run(this.now());
    } finally {
      this.db.pragma(`busy_timeout = ${busy}`);
    }
  }
}
