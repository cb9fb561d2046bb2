// The embedded store: the AsyncStore contract over the synchronous better-sqlite3 Store. SQLite
// runs each statement to the end before any other code, so every method settles at once; the
// sync Store stays reachable (`sync`) for code not yet asynchronous.
import type { Database } from 'better-sqlite3';
import { schemaVersion } from '../migrate.ts';
import type { AsyncStore } from './contract.ts';
import { Store } from './sqlite-sync.ts';
import type { MatchFilter, NewMatch, NewRoom, PracticeRun, RecordSource, RoomChange } from './types.ts';

export class SqliteStore implements AsyncStore {
  readonly engine = 'sqlite';
  constructor(
    readonly db: Database,
    now: () => number = Date.now,
    /** The sync Store to serve: the one the game service writes through, so that they share its caches. */
    readonly sync: Store = new Store(db, now),
  ) {}

  async playerByTokenHash(hash: Buffer) {
    return this.sync.playerByTokenHash(hash);
  }
  async playerById(id: number) {
    return this.sync.playerById(id);
  }
  async nameOwner(name: string, exceptId?: number) {
    return this.sync.nameOwner(name, exceptId);
  }
  async createPlayer(name: string, tokenHash: Buffer) {
    return this.sync.createPlayer(name, tokenHash);
  }
  async computerPlayer(level: number, name: string, tokenHash: Buffer) {
    return this.sync.computerPlayer(level, name, tokenHash);
  }
  async renamePlayer(id: number, name: string) {
    this.sync.renamePlayer(id, name);
  }
  async touchPlayer(id: number) {
    this.sync.touchPlayer(id);
  }
  async fillNameKeys() {
    return this.sync.fillNameKeys();
  }
  async idlePlayers(after: number, cutoff: number, limit: number) {
    return this.sync.idlePlayers(after, cutoff, limit);
  }
  async deletePlayers(ids: readonly number[]) {
    return this.sync.deletePlayers(ids);
  }
  async createRoom(r: NewRoom) {
    this.sync.createRoom(r);
  }
  async createMatch(m: NewMatch) {
    return this.sync.createMatch(m);
  }
  async saveChanges(...changes: RoomChange[]) {
    this.sync.saveChanges(...changes);
  }
  async startMatch(m: NewMatch, change: (matchId: number) => RoomChange) {
    return this.sync.startMatch(m, change);
  }
  async openRooms() {
    return this.sync.openRooms();
  }
  async room(id: string) {
    return this.sync.room(id);
  }
  async matchActions(matchId: number) {
    return this.sync.matchActions(matchId);
  }
  async shotCounts(matchId: number) {
    return this.sync.shotCounts(matchId);
  }
  async matchStartedAt(matchId: number) {
    return this.sync.matchStartedAt(matchId);
  }
  async matchResult(matchId: number) {
    return this.sync.matchResult(matchId);
  }
  async resultCount() {
    return this.sync.resultCount();
  }
  async leaderboard(kind: string, limit: number, offset: number) {
    return this.sync.leaderboard(kind, limit, offset);
  }
  async ratingsOf(playerId: number) {
    return this.sync.ratingsOf(playerId);
  }
  async records(kind: string, limit: number, offset: number, source?: RecordSource) {
    return this.sync.records(kind, limit, offset, source);
  }
  async bestRecordsOf(playerId: number) {
    return this.sync.bestRecordsOf(playerId);
  }
  async matches(filter: MatchFilter, limit: number, offset: number) {
    return this.sync.matches(filter, limit, offset);
  }
  async match(id: number) {
    return this.sync.match(id);
  }
  async issuePracticeSeed(player: number, kind: string, seed: number) {
    return this.sync.issuePracticeSeed(player, kind, seed);
  }
  async sweepPracticeSeeds() {
    return this.sync.sweepPracticeSeeds();
  }
  async practiceSeedState(player: number, kind: string, seed: number) {
    return this.sync.practiceSeedState(player, kind, seed);
  }
  async savePractice(run: PracticeRun) {
    return this.sync.savePractice(run);
  }
  async probeWrite(waitMs: number) {
    this.sync.probeWrite(waitMs);
  }
  async schemaVersion() {
    return schemaVersion(this.db);
  }
  async close() {
    if (this.db.open) this.db.close();
  }
}
