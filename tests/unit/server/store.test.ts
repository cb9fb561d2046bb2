// The store's finish of a match: result, ratings and records in one transaction, exactly once.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { openDatabase } from '../../../server/database.ts';
import { Store, type RoomChange } from '../../../server/store.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';

const closers: (() => void)[] = [];
afterEach(() => closers.splice(0).forEach((c) => c()));

function open() {
  const { db } = openDatabase(join(tempDir('baize-store-'), 'baize.db'), join(ROOT, 'migrations'));
  closers.push(() => db.close());
  const store = new Store(db, () => 1_800_000_000_000);
  const a = store.createPlayer('Ann', Buffer.alloc(32, 1));
  const b = store.createPlayer('Bob', Buffer.alloc(32, 2));
  store.createRoom({ id: 'r1', kind: 'snooker', raceTo: 1, private: false, shotClock: 0, createdBy: a.id, status: 'playing', state: '{}' });
  const match = store.createMatch({ roomId: 'r1', kind: 'snooker', raceTo: 1, player1: a.id, player2: b.id, seed: 1, start: '{}' });
  const finish = (rated: boolean): RoomChange => ({
    roomId: 'r1',
    status: 'over',
    state: '{}',
    result: { matchId: match, kind: 'snooker', winner: a.id, loser: b.id, how: 'played', scores: '{}', rated, records: [{ what: 'break', player: a.id, value: 37, better: 37 }] },
  });
  return { store, a, b, finish };
}

describe('the store', () => {
  it('writes a result, both ratings and the records once, however often the finish is retried', () => {
    const { store, a, b, finish } = open();
    store.saveChanges(finish(true));
    store.saveChanges(finish(true));
    expect(store.resultCount()).toBe(1);
    const board = store.leaderboard('snooker', 10, 0);
    expect(board.total).toBe(2);
    expect(board.rows.map((r) => [r.id, r.games, r.wins])).toEqual([
      [a.id, 1, 1],
      [b.id, 1, 0],
    ]);
    expect(store.records('snooker', 10, 0).map((r) => [r.playerId, r.value])).toEqual([[a.id, 37]]);
  });

  it('leaves the ratings alone for a result that is not rated, and rolls back a failing finish whole', () => {
    const { store, finish } = open();
    store.saveChanges(finish(false));
    expect(store.leaderboard('snooker', 10, 0).total).toBe(0);
    const { store: s2, finish: f2 } = open();
    const bad = f2(true);
    // A record naming a player who does not exist fails its foreign key: nothing of the finish stays.
    expect(() => s2.saveChanges({ ...bad, result: { ...bad.result!, records: [{ what: 'break', player: 999, value: 1, better: 1 }] } })).toThrow();
    expect(s2.resultCount()).toBe(0);
    expect(s2.leaderboard('snooker', 10, 0).total).toBe(0);
  });
});
