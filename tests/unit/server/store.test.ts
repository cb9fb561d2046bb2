// The store's finish of a match: result, ratings and records in one transaction, exactly once; the
// leaderboard of established ratings; the daily limit of rated results between two players.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { openDatabase } from '../../../server/database.ts';
import { Store, type RoomChange } from '../../../server/store/index.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';

const closers: (() => void)[] = [];
afterEach(() => closers.splice(0).forEach((c) => c()));

const HOUR = 3_600_000;

function open() {
  const { db } = openDatabase(join(tempDir('baize-store-'), 'baize.db'), join(ROOT, 'migrations'));
  closers.push(() => db.close());
  const t = { now: 1_800_000_000_000 };
  const store = new Store(db, () => t.now);
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
  /** A new match of a kind between two players, finished now: whether the store rated it, and why not. */
  const play = (kind: string, winner: number, loser: number) => {
    const id = store.createMatch({ roomId: 'r1', kind, raceTo: 1, player1: winner, player2: loser, seed: 1, start: '{}' });
    store.saveChanges({ roomId: 'r1', status: 'over', state: '{}', result: { matchId: id, kind, winner, loser, how: 'played', scores: '{}', rated: true, records: [] } });
    const r = store.matchResult(id)!;
    return r.rated ? 'rated' : r.unrated;
  };
  const setRating = (player: number, kind: string, rating: number, rd: number) =>
    db.prepare('INSERT OR REPLACE INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES (?, ?, ?, ?, 0.06, 30, 15, 0)').run(kind, player, rating, rd);
  return { db, store, t, a, b, finish, play, setRating };
}

const ratingOf = (store: Store, player: number, kind: string) => store.ratingsOf(player).find((r) => r.kind === kind);

describe('the store', () => {
  it('writes a result, both ratings and the records once, however often the finish is retried', () => {
    const { store, a, b, finish } = open();
    store.saveChanges(finish(true));
    store.saveChanges(finish(true));
    expect(store.resultCount()).toBe(1);
    expect(ratingOf(store, a.id, 'snooker')).toMatchObject({ games: 1, wins: 1 });
    expect(ratingOf(store, b.id, 'snooker')).toMatchObject({ games: 1, wins: 0 });
    expect(ratingOf(store, a.id, 'snooker')!.rating).toBeGreaterThan(ratingOf(store, b.id, 'snooker')!.rating);
    // One game is far from an established rating: nobody is on the board yet.
    expect(store.leaderboard('snooker', 10, 0)).toEqual({ total: 0, rows: [] });
    expect(store.records('snooker', 10, 0).map((r) => [r.playerId, r.value])).toEqual([[a.id, 37]]);
  });

  it('leaves the ratings alone for a result that is not rated, and rolls back a failing finish whole', () => {
    const { store, a, finish } = open();
    store.saveChanges(finish(false));
    expect(store.ratingsOf(a.id)).toEqual([]);
    expect(store.matchResult(1)).toMatchObject({ rated: false, unrated: 'few-shots' });
    const { store: s2, a: a2, finish: f2 } = open();
    const bad = f2(true);
    // A record naming a player who does not exist fails its foreign key: nothing of the finish stays.
    expect(() => s2.saveChanges({ ...bad, result: { ...bad.result!, records: [{ what: 'break', player: 999, value: 1, better: 1 }] } })).toThrow();
    expect(s2.resultCount()).toBe(0);
    expect(s2.ratingsOf(a2.id)).toEqual([]);
  });

  it('lists established ratings only (RD under 110), ranked among themselves, and counts only them', () => {
    const { store, setRating } = open();
    const ids = ['Cat', 'Dan', 'Eve', 'Fay', 'Gus'].map((name, i) => store.createPlayer(name, Buffer.alloc(32, 10 + i)).id);
    setRating(ids[0]!, 'nineball', 2600, 140); // a farmed rating: high, but provisional
    setRating(ids[1]!, 'nineball', 1700, 109.99);
    setRating(ids[2]!, 'nineball', 1900, 110); // exactly the threshold: provisional
    setRating(ids[3]!, 'nineball', 1600, 60);
    setRating(ids[4]!, 'snooker', 1800, 50); // another kind
    const board = store.leaderboard('nineball', 10, 0);
    expect(board.total).toBe(2);
    expect(board.rows.map((r) => [r.id, r.rating])).toEqual([
      [ids[1], 1700],
      [ids[3], 1600],
    ]);
    expect(store.leaderboard('nineball', 1, 1).rows.map((r) => r.id)).toEqual([ids[3]]);
    // The player's own ratings still include the provisional one.
    expect(store.ratingsOf(ids[0]!)).toMatchObject([{ kind: 'nineball', rating: 2600, rd: 140 }]);
  });

  it('rates at most 3 results of a kind between the same two players (either order) in any 24 hours', () => {
    const { store, t, a, b, play } = open();
    const c = store.createPlayer('Cid', Buffer.alloc(32, 3));
    const t0 = t.now;
    const results = [];
    for (let i = 0; i < 6; i++) {
      results.push(i % 2 === 0 ? play('nineball', a.id, b.id) : play('nineball', b.id, a.id));
      t.now += HOUR;
    }
    expect(results).toEqual(['rated', 'rated', 'rated', 'pair-limit', 'pair-limit', 'pair-limit']);
    // Another kind, and another opponent, have limits of their own.
    expect(play('eightball', a.id, b.id)).toBe('rated');
    expect(play('nineball', a.id, c.id)).toBe('rated');
    // The window rolls: 24 hours after the first rated result, one more may be rated.
    t.now = t0 + 24 * HOUR - 1;
    expect(play('nineball', b.id, a.id)).toBe('pair-limit');
    t.now += 1;
    expect(play('nineball', b.id, a.id)).toBe('rated');
    expect(play('nineball', b.id, a.id)).toBe('pair-limit');
    expect(ratingOf(store, a.id, 'nineball')!.games).toBe(5);
  });
});
