// Every SQL statement of the server: players, rooms, matches with their action logs, results.
// Each write that belongs together is one transaction, so a crash leaves either all of it or none.
import type { Database } from 'better-sqlite3';

export interface PlayerRow {
  readonly id: number;
  readonly name: string;
}

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
}

export interface MatchResult {
  readonly matchId: number;
  readonly winner: number;
  readonly loser: number;
  readonly how: string;
  readonly scores: string;
}

/** One change of a room: its new snapshot, and the action that made it in its match's log. */
export interface RoomChange {
  readonly roomId: string;
  readonly status: string;
  readonly state: string;
  readonly action?: { readonly matchId: number; readonly seq: number; readonly json: string };
  readonly result?: MatchResult;
}

export class Store {
  private readonly s;

  constructor(
    private readonly db: Database,
    private readonly now: () => number = Date.now,
  ) {
    this.s = {
      playerByToken: db.prepare<[Buffer], PlayerRow>('SELECT id, name FROM players WHERE token_hash = ?'),
      playerById: db.prepare<[number], PlayerRow>('SELECT id, name FROM players WHERE id = ?'),
      nameTaken: db.prepare<[string], { one: number }>('SELECT 1 AS one FROM players WHERE name = ? COLLATE NOCASE'),
      insertPlayer: db.prepare<[string, Buffer, number]>('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, ?)'),
      insertRoom: db.prepare<[string, string, number, number, number, number, number, string, string, number]>(
        'INSERT INTO rooms (id, kind, race_to, private, shot_clock, created_by, created_at, status, state, updated_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)',
      ),
      updateRoom: db.prepare<[string, string, number, string]>('UPDATE rooms SET status = ?, state = ?, updated_at = ? WHERE id = ?'),
      openRooms: db.prepare<[], RoomRow>("SELECT id, status, state FROM rooms WHERE status IN ('waiting', 'playing', 'over') ORDER BY created_at, id"),
      insertMatch: db.prepare<[string, string, number, number, number, number, number]>(
        'INSERT INTO matches (room_id, kind, race_to, player1, player2, seed, started_at) VALUES (?, ?, ?, ?, ?, ?, ?)',
      ),
      insertAction: db.prepare<[number, number, string, number]>('INSERT INTO match_actions (match_id, seq, action, created_at) VALUES (?, ?, ?, ?)'),
      actions: db.prepare<[number], { seq: number; action: string }>('SELECT seq, action FROM match_actions WHERE match_id = ? ORDER BY seq'),
      insertResult: db.prepare<[number, number, number, string, string, number]>(
        'INSERT OR IGNORE INTO results (match_id, winner, loser, how, scores, finished_at) VALUES (?, ?, ?, ?, ?, ?)',
      ),
      finishMatch: db.prepare<[number, number]>('UPDATE matches SET finished_at = ? WHERE id = ? AND finished_at IS NULL'),
      result: db.prepare<[number], { winner: number; loser: number; how: string; scores: string }>('SELECT winner, loser, how, scores FROM results WHERE match_id = ?'),
      resultCount: db.prepare<[], { n: number }>('SELECT count(*) AS n FROM results'),
    };
  }

  playerByTokenHash(hash: Buffer): PlayerRow | undefined {
    return this.s.playerByToken.get(hash);
  }

  playerById(id: number): PlayerRow | undefined {
    return this.s.playerById.get(id);
  }

  nameTaken(name: string): boolean {
    return this.s.nameTaken.get(name) !== undefined;
  }

  /** A new player; throws on a name taken meanwhile (the UNIQUE constraint). */
  createPlayer(name: string, tokenHash: Buffer): PlayerRow {
    const info = this.s.insertPlayer.run(name, tokenHash, this.now());
    return { id: Number(info.lastInsertRowid), name };
  }

  createRoom(r: NewRoom): void {
    const now = this.now();
    this.s.insertRoom.run(r.id, r.kind, r.raceTo, r.private ? 1 : 0, r.shotClock, r.createdBy, now, r.status, r.state, now);
  }

  /** Starts a match and returns its id. */
  createMatch(m: NewMatch): number {
    const info = this.s.insertMatch.run(m.roomId, m.kind, m.raceTo, m.player1, m.player2, m.seed, this.now());
    return Number(info.lastInsertRowid);
  }

  /** Changes of rooms, their actions and any results, in one transaction. */
  saveChanges(...changes: RoomChange[]): void {
    this.db.transaction(() => {
      const now = this.now();
      for (const c of changes) {
        if (c.action) this.s.insertAction.run(c.action.matchId, c.action.seq, c.action.json, now);
        if (c.result) {
          // A result is written once: a retried finish finds it there and adds nothing.
          this.s.insertResult.run(c.result.matchId, c.result.winner, c.result.loser, c.result.how, c.result.scores, now);
          this.s.finishMatch.run(now, c.result.matchId);
        }
        this.s.updateRoom.run(c.status, c.state, now, c.roomId);
      }
    })();
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

  matchActions(matchId: number): { seq: number; action: unknown }[] {
    return this.s.actions.all(matchId).map((r) => ({ seq: r.seq, action: JSON.parse(r.action) as unknown }));
  }

  matchResult(matchId: number): { winner: number; loser: number; how: string; scores: unknown } | undefined {
    const r = this.s.result.get(matchId);
    return r && { ...r, scores: JSON.parse(r.scores) as unknown };
  }

  resultCount(): number {
    return this.s.resultCount.get()!.n;
  }
}
