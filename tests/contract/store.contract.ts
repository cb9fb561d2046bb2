// The store's contract, one suite for every implementation of AsyncStore: call storeContract inside
// a describe with a function that opens a fresh, migrated, empty store on a test clock. SQLite
// (tests/unit/server/store-sqlite.test.ts) and PostgreSQL (tests/integration/store-postgres.test.ts)
// must answer each of these alike.
import fc from 'fast-check';
import { afterEach, expect, it } from 'vitest';
import { OPEN_ROOMS_PER_PLAYER, PRACTICE_OPEN_SEEDS, PRACTICE_SEED_TTL_MS, PracticeSeedError, StaleRoomError, TooManyRoomsError, type AsyncStore, type PlayerRow, type RoomChange } from '../../server/store/index.ts';

export interface StoreHarness {
  readonly store: AsyncStore;
  /** The store's clock (ms); tests move it. */
  readonly clock: { now: number };
  /** Rows in a table, read beside the store: what a refused write must leave as it was. */
  count(table: string): Promise<number>;
  /** A rating put straight into its table (an established one takes dozens of games). */
  setRating(player: number, kind: string, rating: number, rd: number): Promise<void>;
  /** A player as stored before the name keys (migration 006): no keys. */
  insertKeyless(name: string, tokenHash: Buffer): Promise<number>;
  /** Holds the write lock the health probe needs (another connection's open write) until released. */
  holdHealthLock(): Promise<() => Promise<void>>;
  close(): Promise<void>;
}

export const T0 = 1_800_000_000_000;
const HOUR = 3_600_000;
/** Migrations in migrations/ (and migrations/postgres/): the schema version of a fresh store. */
const SCHEMA = 10;

const hash = (n: number) => Buffer.alloc(32, n);

export function storeContract(openStore: () => Promise<StoreHarness>): void {
  const open: StoreHarness[] = [];
  afterEach(async () => {
    for (const h of open.splice(0)) await h.close();
  });

  /** A fresh store with Ann and Bob, a snooker room r1 by Ann and a match between them. */
  async function fresh() {
    const h = await openStore();
    open.push(h);
    const { store } = h;
    const a = await store.createPlayer('Ann', hash(1));
    const b = await store.createPlayer('Bob', hash(2));
    await store.createRoom({ id: 'r1', kind: 'snooker', raceTo: 1, private: false, shotClock: 0, createdBy: a.id, status: 'playing', state: '{"v":0}' });
    const match = await store.createMatch({ roomId: 'r1', kind: 'snooker', raceTo: 1, player1: a.id, player2: b.id, seed: 1, start: '{"start":1}' });
    const finish = (rated: boolean, records = [{ what: 'break', player: a.id, value: 37, better: 37 }]): RoomChange => ({
      roomId: 'r1',
      status: 'over',
      state: '{"v":9}',
      result: { matchId: match, kind: 'snooker', winner: a.id, loser: b.id, how: 'played', scores: '{"a":1}', rated, records },
    });
    /** A new match of a kind, finished now: whether the store rated it, and why not. */
    const play = async (kind: string, winner: number, loser: number) => {
      const id = await store.createMatch({ roomId: 'r1', kind, raceTo: 1, player1: winner, player2: loser, seed: 1, start: '{}' });
      await store.saveChanges({ roomId: 'r1', status: 'over', state: '{}', result: { matchId: id, kind, winner, loser, how: 'played', scores: '{}', rated: true, records: [] } });
      const r = (await store.matchResult(id))!;
      return r.rated ? 'rated' : r.unrated;
    };
    return { ...h, a, b, match, finish, play };
  }

  const ratingOf = async (store: AsyncStore, player: number, kind: string) => (await store.ratingsOf(player)).find((r) => r.kind === kind);

  // Players and their names.

  it('keeps players: by id, by token with when last seen, touched; unknown ones are undefined', async () => {
    const { store, clock, a } = await fresh();
    expect(a).toEqual({ id: expect.any(Number), name: 'Ann' });
    expect(await store.playerById(a.id)).toEqual({ id: a.id, name: 'Ann' });
    expect(await store.playerByTokenHash(hash(1))).toEqual({ id: a.id, name: 'Ann', lastSeen: T0 });
    clock.now += 5000;
    await store.touchPlayer(a.id);
    expect((await store.playerByTokenHash(hash(1)))!.lastSeen).toBe(T0 + 5000);
    expect(await store.playerById(999_999)).toBeUndefined();
    expect(await store.playerByTokenHash(hash(99))).toBeUndefined();
    expect(await store.fillNameKeys()).toBe(0); // every player made through the store has its keys
  });

  it('owns a name and its lookalikes: another case or script is taken, a rename frees the old one', async () => {
    const { store, a, b } = await fresh();
    expect(await store.nameOwner('ann')).toBe(a.id);
    expect(await store.nameOwner('ANN')).toBe(a.id);
    expect(await store.nameOwner('\u0410nn')).toBe(a.id); // a Cyrillic A
    expect(await store.nameOwner('Ann', a.id)).toBeUndefined(); // one's own name
    expect(await store.nameOwner('Cid')).toBeUndefined();
    await expect(store.createPlayer('aNN', hash(3))).rejects.toThrow();
    await expect(store.createPlayer('Cid', hash(1))).rejects.toThrow(); // a token is one player's
    await expect(store.renamePlayer(b.id, 'ann')).rejects.toThrow();
    expect(await store.playerById(b.id)).toEqual({ id: b.id, name: 'Bob' });
    await store.renamePlayer(a.id, 'ANNA');
    expect(await store.playerById(a.id)).toEqual({ id: a.id, name: 'ANNA' });
    expect(await store.nameOwner('Ann')).toBeUndefined();
    expect(await store.nameOwner('anna')).toBe(a.id);
    const c = await store.createPlayer('Ann', hash(3));
    expect(await store.nameOwner('ann')).toBe(c.id);
  });

  it('gives players from before the name keys theirs, the older keeping a key two share', async () => {
    const { store, insertKeyless } = await fresh();
    const old1 = await insertKeyless('Zed', hash(80));
    const old2 = await insertKeyless('\u0396ed', hash(81)); // a Greek Zeta: its upper key is Zed's
    const old3 = await insertKeyless('Yan', hash(82));
    expect(await store.nameOwner('zed')).toBeUndefined(); // no keys yet
    expect(await store.fillNameKeys()).toBe(3);
    expect(await store.fillNameKeys()).toBe(0);
    expect(await store.nameOwner('ZED')).toBe(old1);
    expect(await store.nameOwner('yan')).toBe(old3);
    // The later lookalike keeps its name and its own lower key; the shared upper key stays the older's.
    expect(await store.playerById(old2)).toEqual({ id: old2, name: '\u0396ed' });
    expect(await store.nameOwner('\u0396ed', old2)).toBe(old1);
    expect(await store.nameOwner('\u0396ed', old1)).toBe(old2);
    await expect(store.createPlayer('zed', hash(83))).rejects.toThrow();
    await expect(store.createPlayer('YAN', hash(84))).rejects.toThrow();
  });

  it('makes one player of a name asked for twice at once', async () => {
    const { store } = await fresh();
    const made = await Promise.allSettled([store.createPlayer('Dee', hash(90)), store.createPlayer('DEE', hash(91))]);
    expect(made.map((m) => m.status).sort()).toEqual(['fulfilled', 'rejected']);
  });

  it("makes the computer's player of a level once, however many ask at once, and never rates its matches", async () => {
    const { store, a } = await fresh();
    const rows = await Promise.all([1, 2, 3].map((i) => store.computerPlayer(2, 'Computer 2', hash(40 + i))));
    expect(new Set(rows.map((r) => r.id)).size).toBe(1);
    expect(await store.computerPlayer(2, 'Computer 2', hash(50))).toEqual(rows[0]);
    const other = await store.computerPlayer(3, 'Computer 3', hash(51));
    expect(other.id).not.toBe(rows[0]!.id);
    const id = await store.createMatch({ roomId: 'r1', kind: 'nineball', raceTo: 1, player1: a.id, player2: other.id, seed: 1, start: '{}' });
    await store.saveChanges({ roomId: 'r1', status: 'over', state: '{}', result: { matchId: id, kind: 'nineball', winner: a.id, loser: other.id, how: 'played', scores: '{}', rated: true, records: [] } });
    expect(await store.matchResult(id)).toMatchObject({ rated: false, unrated: 'computer' });
    expect(await store.ratingsOf(a.id)).toEqual([]);
  });

  it('lists idle players by pages and deletes them, keeping any a row refers to', async () => {
    const { store, clock, a, b } = await fresh();
    const idle: PlayerRow[] = [];
    for (let i = 0; i < 5; i++) idle.push(await store.createPlayer(`Idle${i}`, hash(60 + i)));
    clock.now += 10 * HOUR;
    const seen = await store.createPlayer('Seen', hash(70));
    const cutoff = clock.now - HOUR;
    const found: number[] = [];
    let after = 0;
    for (let pages = 0; pages < 10; pages++) {
      const page = await store.idlePlayers(after, cutoff, 3);
      found.push(...page.idle);
      if (page.next === undefined) break;
      after = page.next;
    }
    // Ann made a room and Bob plays a match: not idle. Seen was seen after the cutoff.
    expect(found).toEqual(idle.map((p) => p.id));
    expect(await store.deletePlayers([...found, a.id, b.id])).toBe(5);
    expect(await store.playerById(idle[0]!.id)).toBeUndefined();
    expect(await store.playerById(a.id)).toEqual(a);
    expect(await store.playerById(seen.id)).toEqual(seen);
    expect(await store.deletePlayers([])).toBe(0);
  });

  // Rooms, matches, their actions and results.

  it('brings back rooms not closed, oldest first, as last changed, with their match logs', async () => {
    const { store, clock, a, b, match } = await fresh();
    clock.now += 1;
    await store.createRoom({ id: 'r0', kind: 'nineball', raceTo: 2, private: true, shotClock: 30, createdBy: b.id, status: 'waiting', state: '{"w":1}' });
    clock.now += 1;
    await store.createRoom({ id: 'r2', kind: 'threecushion', raceTo: 1, private: false, shotClock: 0, createdBy: a.id, status: 'playing', state: '{}' });
    await store.saveChanges(
      { roomId: 'r1', status: 'playing', state: '{"v":1}', action: { matchId: match, seq: 1, json: JSON.stringify({ type: 'shot', player: String(a.id) }) } },
      { roomId: 'r2', status: 'closed', state: '{"closed":true}' },
    );
    await store.saveChanges({ roomId: 'r1', status: 'playing', state: '{"v":2}', action: { matchId: match, seq: 2, json: JSON.stringify({ type: 'shot', player: String(b.id) }) } });
    await store.saveChanges({ roomId: 'r1', status: 'playing', state: '{"v":3}', action: { matchId: match, seq: 3, json: JSON.stringify({ type: 'shot', player: String(a.id) }) } });
    await store.saveChanges({ roomId: 'r1', status: 'playing', state: '{"v":4}', action: { matchId: match, seq: 4, json: JSON.stringify({ type: 'concede', player: String(b.id) }) } });
    expect(await store.openRooms()).toEqual([
      { id: 'r1', status: 'playing', state: '{"v":4}' },
      { id: 'r0', status: 'waiting', state: '{"w":1}' },
    ]);
    expect(await store.room('r2')).toEqual({ id: 'r2', status: 'closed', state: '{"closed":true}' });
    expect(await store.room('r1')).toEqual({ id: 'r1', status: 'playing', state: '{"v":4}' });
    expect(await store.room('nowhere')).toBeUndefined();
    expect((await store.matchActions(match)).map((x) => x.seq)).toEqual([1, 2, 3, 4]);
    expect((await store.matchActions(match))[3]).toEqual({ seq: 4, action: { type: 'concede', player: String(b.id) } });
    expect(await store.shotCounts(match)).toEqual(new Map([[String(a.id), 2], [String(b.id), 1]]));
    expect(await store.matchStartedAt(match)).toBe(T0);
    expect(await store.matchStartedAt(999_999)).toBeUndefined();
    expect(await store.matchActions(999_999)).toEqual([]);
    // An action's place in the log is taken once.
    await expect(store.saveChanges({ roomId: 'r1', status: 'playing', state: '{"v":5}', action: { matchId: match, seq: 4, json: '{}' } })).rejects.toThrow();
    expect((await store.openRooms())[0]!.state).toBe('{"v":4}');
  });

  it('writes a room change only when the room is at the stateId it expects; else nothing of the save', async () => {
    const { store, a, b } = await fresh();
    await store.createRoom({ id: 'r3', kind: 'nineball', raceTo: 1, private: false, shotClock: 0, createdBy: a.id, status: 'playing', state: '{"stateId":0}' });
    const match = await store.createMatch({ roomId: 'r3', kind: 'nineball', raceTo: 1, player1: a.id, player2: b.id, seed: 1, start: '{}' });
    const at = (stateId: number, expect: number, extra: object = {}): RoomChange => ({
      roomId: 'r3', status: 'playing', state: JSON.stringify({ stateId, ...extra }), expectStateId: expect,
      action: { matchId: match, seq: stateId, json: JSON.stringify({ type: 'shot', player: String(a.id) }) },
    });
    const stateOf = async (id: string) => (await store.openRooms()).find((r) => r.id === id)?.state;
    await store.saveChanges(at(1, 0));
    const stale = await store.saveChanges(at(1, 0, { other: true })).catch((err: unknown) => err);
    expect(stale).toBeInstanceOf(StaleRoomError);
    expect(stale).toMatchObject({ roomId: 'r3', expected: 0 });
    // Nothing of a refused save: not the other room's change before it, not its action.
    await expect(store.saveChanges({ roomId: 'r1', status: 'playing', state: '{"v":1}' }, at(2, 0))).rejects.toThrow(StaleRoomError);
    expect(await stateOf('r1')).toBe('{"v":0}');
    expect(await stateOf('r3')).toBe('{"stateId":1}');
    expect((await store.matchActions(match)).map((x) => x.seq)).toEqual([1]);
    await store.saveChanges(at(2, 1));
    // A room that does not exist, or whose state has no stateId, is at no stateId.
    await expect(store.saveChanges({ ...at(3, 2), roomId: 'nowhere' })).rejects.toThrow(StaleRoomError);
    await expect(store.saveChanges({ roomId: 'r1', status: 'over', state: '{}', expectStateId: 0 })).rejects.toThrow(StaleRoomError);
    // Of two writers that read the room at the same stateId and save at once, one commits.
    const both = await Promise.allSettled([store.saveChanges(at(3, 2, { by: 'one' })), store.saveChanges(at(3, 2, { by: 'two' }))]);
    expect(both.map((s) => s.status).sort()).toEqual(['fulfilled', 'rejected']);
    const lost = both.find((s) => s.status === 'rejected') as PromiseRejectedResult;
    expect(lost.reason).toBeInstanceOf(StaleRoomError);
    const won = both.findIndex((s) => s.status === 'fulfilled');
    expect(JSON.parse((await stateOf('r3'))!)).toEqual({ stateId: 3, by: won === 0 ? 'one' : 'two' });
    expect((await store.matchActions(match)).map((x) => x.seq)).toEqual([1, 2, 3]);
  });

  it(`keeps a creator to ${OPEN_ROOMS_PER_PLAYER} rooms waiting or in play: of 8 created at once, exactly ${OPEN_ROOMS_PER_PLAYER} are`, async () => {
    const { store, count } = await fresh();
    const cid = await store.createPlayer('Cid', hash(3));
    const room = (i: number, status = 'waiting') => ({ id: `c${i}`, kind: 'nineball', raceTo: 1, private: false, shotClock: 0, createdBy: cid.id, status, state: '{"stateId":0}' });
    const before = await count('rooms');
    const all = await Promise.allSettled(Array.from({ length: 8 }, (_, i) => store.createRoom(room(i))));
    expect(all.filter((s) => s.status === 'fulfilled')).toHaveLength(OPEN_ROOMS_PER_PLAYER);
    for (const s of all) if (s.status === 'rejected') expect(s.reason).toBeInstanceOf(TooManyRoomsError);
    expect(await count('rooms')).toBe(before + OPEN_ROOMS_PER_PLAYER);
    // A room over (or closed) frees its place; another creator is not held back.
    const made = all.findIndex((s) => s.status === 'fulfilled');
    await store.saveChanges({ roomId: `c${made}`, status: 'over', state: '{}' });
    await store.createRoom(room(8));
    await expect(store.createRoom(room(9))).rejects.toThrow(TooManyRoomsError);
    const dee = await store.createPlayer('Dee', hash(4));
    await store.createRoom({ ...room(10), createdBy: dee.id });
  });

  it('starts a match with its room change in one transaction: a failing change leaves no match', async () => {
    const { store, a, b, count } = await fresh();
    const m = { roomId: 'r1', kind: 'snooker', raceTo: 1, player1: a.id, player2: b.id, seed: 7, start: '{"s":7}' };
    const id = await store.startMatch(m, (matchId) => ({ roomId: 'r1', status: 'playing', state: JSON.stringify({ matchId }) }));
    expect((await store.openRooms())[0]!.state).toBe(JSON.stringify({ matchId: id }));
    expect(await store.match(id)).toMatchObject({ id, kind: 'snooker', player1: a.id, name1: 'Ann', player2: b.id, name2: 'Bob', start: '{"s":7}', winner: null });
    const before = await count('matches');
    // The change logs an action under a match that does not exist: its foreign key refuses.
    await expect(store.startMatch(m, () => ({ roomId: 'r1', status: 'playing', state: '{"bad":1}', action: { matchId: 999_999, seq: 1, json: '{}' } }))).rejects.toThrow();
    expect(await count('matches')).toBe(before);
    expect((await store.openRooms())[0]!.state).toBe(JSON.stringify({ matchId: id }));
  });

  it('writes a result, both ratings and the records once, however often the finish is retried', async () => {
    const { store, a, b, match, finish } = await fresh();
    await store.saveChanges(finish(true));
    await store.saveChanges(finish(true));
    expect(await store.resultCount()).toBe(1);
    expect(await ratingOf(store, a.id, 'snooker')).toMatchObject({ games: 1, wins: 1 });
    expect(await ratingOf(store, b.id, 'snooker')).toMatchObject({ games: 1, wins: 0 });
    expect((await ratingOf(store, a.id, 'snooker'))!.rating).toBeGreaterThan((await ratingOf(store, b.id, 'snooker'))!.rating);
    // One game is far from an established rating: nobody is on the board yet.
    expect(await store.leaderboard('snooker', 10, 0)).toEqual({ total: 0, rows: [] });
    expect((await store.records('snooker', 10, 0)).map((r) => [r.playerId, r.value, r.matchId])).toEqual([[a.id, 37, match]]);
    expect(await store.matchResult(match)).toEqual({ winner: a.id, loser: b.id, how: 'played', scores: { a: 1 }, rated: true, unrated: null });
    expect(await store.match(match)).toMatchObject({ winner: a.id, how: 'played', rated: 1, unrated: null, finishedAt: T0 });
    expect(await store.openRooms()).toEqual([{ id: 'r1', status: 'over', state: '{"v":9}' }]);
  });

  it('leaves the ratings alone for a result that is not rated', async () => {
    const { store, a, match, finish } = await fresh();
    await store.saveChanges(finish(false));
    expect(await store.ratingsOf(a.id)).toEqual([]);
    expect(await store.matchResult(match)).toMatchObject({ rated: false, unrated: 'few-shots' });
    expect(await store.matchResult(999_999)).toBeUndefined();
  });

  it('rolls back a failing save whole: no action, result, rating, record or room change stays', async () => {
    const { store, a, b, match, finish, count } = await fresh();
    await store.createRoom({ id: 'r2', kind: 'snooker', raceTo: 1, private: false, shotClock: 0, createdBy: b.id, status: 'waiting', state: '{"r2":0}' });
    const rooms = await store.openRooms();
    const bad = finish(true, [
      { what: 'break', player: a.id, value: 37, better: 37 },
      { what: 'break', player: 999_999, value: 1, better: 1 }, // no such player: its foreign key refuses
    ]);
    // The first change and the start of the second (its action, the result, both ratings, a
    // record) are written before the failing record.
    await expect(
      store.saveChanges({ roomId: 'r2', status: 'playing', state: '{"r2":1}' }, { ...bad, action: { matchId: match, seq: 1, json: '{"type":"shot"}' } }),
    ).rejects.toThrow();
    expect(await store.openRooms()).toEqual(rooms);
    expect(await store.matchActions(match)).toEqual([]);
    expect(await store.resultCount()).toBe(0);
    expect(await store.ratingsOf(a.id)).toEqual([]);
    expect(await store.ratingsOf(b.id)).toEqual([]);
    expect(await count('records')).toBe(0);
    expect(await store.match(match)).toMatchObject({ finishedAt: null, winner: null });
    // And the store goes on: the same finish without the bad record is written.
    await store.saveChanges(finish(true));
    expect(await store.resultCount()).toBe(1);
  });

  it('lists established ratings only (RD under 110), ranked among themselves, by pages', async () => {
    const { store, setRating } = await fresh();
    const ids: number[] = [];
    for (const [i, name] of ['Cat', 'Dan', 'Eve', 'Fay', 'Gus', 'Hal'].entries()) ids.push((await store.createPlayer(name, hash(10 + i))).id);
    await setRating(ids[0]!, 'nineball', 2600, 140); // a farmed rating: high, but provisional
    await setRating(ids[1]!, 'nineball', 1700, 109.99);
    await setRating(ids[2]!, 'nineball', 1900, 110); // exactly the threshold: provisional
    await setRating(ids[3]!, 'nineball', 1600, 60);
    await setRating(ids[5]!, 'nineball', 1600, 70); // a tie: the lower id first
    await setRating(ids[4]!, 'snooker', 1800, 50); // another kind
    const board = await store.leaderboard('nineball', 10, 0);
    expect(board.total).toBe(3);
    expect(board.rows).toEqual([
      { id: ids[1], name: 'Dan', rating: 1700, rd: 109.99, games: 30, wins: 15 },
      { id: ids[3], name: 'Fay', rating: 1600, rd: 60, games: 30, wins: 15 },
      { id: ids[5], name: 'Hal', rating: 1600, rd: 70, games: 30, wins: 15 },
    ]);
    expect((await store.leaderboard('nineball', 1, 1)).rows.map((r) => r.id)).toEqual([ids[3]]);
    expect(await store.leaderboard('nineball', 10, 3)).toEqual({ total: 3, rows: [] });
    expect(await store.leaderboard('eightball', 10, 0)).toEqual({ total: 0, rows: [] });
    // The player's own ratings include the provisional one, every kind in order.
    await setRating(ids[0]!, 'eightball', 1500, 300);
    expect(await store.ratingsOf(ids[0]!)).toEqual([
      { kind: 'eightball', id: ids[0], name: '', rating: 1500, rd: 300, games: 30, wins: 15 },
      { kind: 'nineball', id: ids[0], name: '', rating: 2600, rd: 140, games: 30, wins: 15 },
    ]);
  });

  it('pages the leaderboard without gaps or repeats: the pages make the board, best first, ties by id (property)', async () => {
    const { store, setRating } = await fresh();
    const ids: number[] = [];
    for (let i = 0; i < 24; i++) ids.push((await store.createPlayer(`Board${i}`, hash(100 + i))).id);
    let round = 0;
    await fc.assert(
      fc.asyncProperty(
        fc.array(fc.record({ who: fc.integer({ min: 0, max: 23 }), rating: fc.integer({ min: 1400, max: 1410 }), rd: fc.constantFrom(50, 109.5, 110, 200) }), { maxLength: 24 }),
        fc.integer({ min: 1, max: 7 }),
        async (ratings, size) => {
          // A kind of its own each round (ratings' kinds are free text), so rounds do not meet.
          const kind = `board${++round}`;
          const latest = new Map<number, { rating: number; rd: number }>();
          for (const r of ratings) {
            await setRating(ids[r.who]!, kind, r.rating, r.rd);
            latest.set(ids[r.who]!, { rating: r.rating, rd: r.rd });
          }
          const expected = [...latest].filter(([, r]) => r.rd < 110).sort(([a, x], [b, y]) => y.rating - x.rating || a - b).map(([id]) => id);
          const paged: number[] = [];
          for (let offset = 0; offset <= expected.length; offset += size) {
            const page = await store.leaderboard(kind, size, offset);
            expect(page.total).toBe(expected.length);
            paged.push(...page.rows.map((r) => r.id));
          }
          expect(paged).toEqual(expected);
        },
      ),
      { numRuns: 20 },
    );
  });

  it('rates at most 3 results of a kind between the same two players (either order) in any 24 hours', async () => {
    const { store, clock, a, b, play } = await fresh();
    const c = await store.createPlayer('Cid', hash(3));
    const t0 = clock.now;
    const results = [];
    for (let i = 0; i < 6; i++) {
      results.push(i % 2 === 0 ? await play('nineball', a.id, b.id) : await play('nineball', b.id, a.id));
      clock.now += HOUR;
    }
    expect(results).toEqual(['rated', 'rated', 'rated', 'pair-limit', 'pair-limit', 'pair-limit']);
    // Another kind, and another opponent, have limits of their own.
    expect(await play('eightball', a.id, b.id)).toBe('rated');
    expect(await play('nineball', a.id, c.id)).toBe('rated');
    // The window rolls: 24 hours after the first rated result, one more may be rated.
    clock.now = t0 + 24 * HOUR - 1;
    expect(await play('nineball', b.id, a.id)).toBe('pair-limit');
    clock.now += 1;
    expect(await play('nineball', b.id, a.id)).toBe('rated');
    expect(await play('nineball', b.id, a.id)).toBe('pair-limit');
    expect((await ratingOf(store, a.id, 'nineball'))!.games).toBe(5);
  });

  it('writes a finish saved twice at once once', async () => {
    const { store, a, finish } = await fresh();
    await Promise.all([store.saveChanges(finish(true)), store.saveChanges(finish(true)), store.saveChanges(finish(true))]);
    expect(await store.resultCount()).toBe(1);
    expect(await ratingOf(store, a.id, 'snooker')).toMatchObject({ games: 1, wins: 1 });
    expect(await store.records('snooker', 10, 0)).toHaveLength(1);
  });

  it('saves results of the same players in opposite orders at once, without a deadlock', async () => {
    const { store, a, b } = await fresh();
    const c = await store.createPlayer('Cid', hash(3));
    const d = await store.createPlayer('Dee', hash(4));
    const result = async (kind: string, winner: number, loser: number): Promise<RoomChange> => {
      const matchId = await store.createMatch({ roomId: 'r1', kind, raceTo: 1, player1: winner, player2: loser, seed: 1, start: '{}' });
      return { roomId: 'r1', status: 'over', state: '{}', result: { matchId, kind, winner, loser, how: 'played', scores: '{}', rated: true, records: [] } };
    };
    for (const kind of ['nineball', 'eightball', 'snooker']) {
      const one = [await result(kind, a.id, b.id), await result(kind, c.id, d.id)];
      const two = [await result(kind, d.id, c.id), await result(kind, b.id, a.id)];
      await Promise.all([store.saveChanges(...one), store.saveChanges(...two)]);
    }
    expect(await store.resultCount()).toBe(12);
    for (const p of [a, b, c, d]) expect((await store.ratingsOf(p.id)).map((r) => r.games)).toEqual([2, 2, 2]);
  });

  it('holds the pair limit and loses no rating update when results are saved at once', async () => {
    const { store, a, b, play } = await fresh();
    const c = await store.createPlayer('Cid', hash(3));
    const outcomes = await Promise.all([...Array.from({ length: 6 }, (_, i) => (i % 2 ? play('nineball', a.id, b.id) : play('nineball', b.id, a.id))), play('nineball', a.id, c.id), play('nineball', c.id, a.id)]);
    expect(outcomes.slice(0, 6).filter((o) => o === 'rated')).toHaveLength(3);
    expect(outcomes.slice(6)).toEqual(['rated', 'rated']);
    // Every rated result moved both of its players' ratings: none overwrote another.
    expect(await ratingOf(store, a.id, 'nineball')).toMatchObject({ games: 5 });
    expect((await ratingOf(store, b.id, 'nineball'))!.games + (await ratingOf(store, c.id, 'nineball'))!.games).toBe(5);
  });

  it('pages records best first, each player\'s best of a kind, and matches newest first by player and kind', async () => {
    const { store, a, b, match, finish } = await fresh();
    await store.saveChanges(finish(true, [{ what: 'break', player: a.id, value: 37, better: 37 }, { what: 'break', player: b.id, value: 50, better: 50 }]));
    const ids = [match];
    for (const [kind, p1, p2] of [['nineball', a.id, b.id], ['threecushion', b.id, a.id], ['nineball', b.id, a.id]] as const) {
      const id = await store.createMatch({ roomId: 'r1', kind, raceTo: 1, player1: p1, player2: p2, seed: 2, start: '{}' });
      ids.push(id);
      const records = kind === 'nineball' ? [{ what: 'break-and-run', player: p1, value: 9 + ids.length, better: -(9 + ids.length) }] : [{ what: 'run', player: p1, value: 4, better: 4 }];
      await store.saveChanges({ roomId: 'r1', status: 'over', state: '{}', result: { matchId: id, kind, winner: p1, loser: p2, how: 'played', scores: '{}', rated: false, records } });
    }
    const other = await store.createPlayer('Cid', hash(3));
    ids.push(await store.createMatch({ roomId: 'r1', kind: 'nineball', raceTo: 1, player1: other.id, player2: b.id, seed: 3, start: '{}' }));
    expect((await store.records('snooker', 10, 0)).map((r) => [r.name, r.value])).toEqual([['Bob', 50], ['Ann', 37]]);
    expect((await store.records('snooker', 1, 1)).map((r) => r.name)).toEqual(['Ann']);
    expect(await store.records('snooker', 10, 0, 'practice')).toEqual([]);
    const best = await store.records('nineball', 10, 0);
    expect(best.map((r) => [r.name, r.value])).toEqual([['Ann', 11], ['Bob', 13]]);
    expect(best[0]).toEqual({ id: expect.any(Number), kind: 'nineball', what: 'break-and-run', playerId: a.id, name: 'Ann', value: 11, matchId: ids[1], practiceId: null, createdAt: T0 });
    expect((await store.bestRecordsOf(b.id)).map((r) => [r.kind, r.value])).toEqual([['nineball', 13], ['snooker', 50], ['threecushion', 4]]);
    expect(await store.bestRecordsOf(other.id)).toEqual([]);
    const listed = async (filter: { player?: number; kind?: string }, limit = 10, offset = 0) => (await store.matches(filter, limit, offset)).map((m) => m.id);
    expect(await listed({})).toEqual([...ids].reverse());
    expect(await listed({}, 2, 1)).toEqual([ids[3], ids[2]]);
    expect(await listed({ kind: 'nineball' })).toEqual([ids[4], ids[3], ids[1]]);
    expect(await listed({ player: a.id })).toEqual([ids[3], ids[2], ids[1], ids[0]]);
    expect(await listed({ player: a.id, kind: 'nineball' })).toEqual([ids[3], ids[1]]);
    expect(await listed({ player: b.id }, 2, 2)).toEqual([ids[2], ids[1]]);
    expect(await listed({ player: 999_999 })).toEqual([]);
    expect((await store.matches({ player: other.id }, 10, 0))[0]).toEqual({
      id: ids[4], kind: 'nineball', raceTo: 1, player1: other.id, name1: 'Cid', player2: b.id, name2: 'Bob',
      startedAt: T0, finishedAt: null, winner: null, how: null, rated: null, unrated: null,
    });
    expect(await store.match(999_999)).toBeUndefined();
  });

  // Practice.

  const run = (player: number, seed: number, better = 10, kind = 'snooker') => ({ player, kind, seed, shots: '[]', score: better, records: [{ what: 'break', player, value: better, better }] });

  it('uses a practice seed once, by its player, for its kind; a refused save writes nothing', async () => {
    const { store, a, b, count } = await fresh();
    expect(await store.issuePracticeSeed(a.id, 'snooker', 42)).toBe(T0);
    expect(await store.issuePracticeSeed(a.id, 'snooker', 42)).toBeNull(); // held already: draw another
    expect(await store.practiceSeedState(a.id, 'snooker', 42)).toBe('open');
    expect(await store.practiceSeedState(b.id, 'snooker', 42)).toBe('unknown');
    expect(await store.practiceSeedState(a.id, 'nineball', 42)).toBe('unknown');
    await expect(store.savePractice(run(b.id, 42))).rejects.toThrow(PracticeSeedError);
    await expect(store.savePractice(run(a.id, 42, 10, 'nineball'))).rejects.toThrow(PracticeSeedError);
    expect(await count('practice_runs')).toBe(0);
    expect(await count('records')).toBe(0);
    const saved = await store.savePractice(run(a.id, 42));
    expect(saved).toEqual({ id: expect.any(Number), standing: [true] });
    expect(await store.practiceSeedState(a.id, 'snooker', 42)).toBe('used');
    const again = await store.savePractice(run(a.id, 42, 99)).catch((err: unknown) => err);
    expect(again).toBeInstanceOf(PracticeSeedError);
    expect((again as PracticeSeedError).state).toBe('used');
    expect(await count('practice_runs')).toBe(1);
    expect((await store.records('snooker', 10, 0, 'practice')).map((r) => [r.value, r.practiceId, r.matchId])).toEqual([[10, saved.id, null]]);
    expect(await store.records('snooker', 10, 0, 'match')).toEqual([]);
  });

  it('uses a practice seed once when two runs from it are saved at once', async () => {
    const { store, a, count } = await fresh();
    await store.issuePracticeSeed(a.id, 'snooker', 5);
    const saved = await Promise.allSettled([store.savePractice(run(a.id, 5, 10)), store.savePractice(run(a.id, 5, 20)), store.savePractice(run(a.id, 5, 30))]);
    expect(saved.filter((s) => s.status === 'fulfilled')).toHaveLength(1);
    for (const s of saved) if (s.status === 'rejected') expect(s.reason).toMatchObject({ state: 'used' });
    expect(await count('practice_runs')).toBe(1);
    expect(await store.records('snooker', 10, 0, 'practice')).toHaveLength(1);
  });

  it('expires practice seeds after their lifetime, and deletes them then, used or not', async () => {
    const { store, clock, a, count } = await fresh();
    await store.issuePracticeSeed(a.id, 'snooker', 1);
    await store.issuePracticeSeed(a.id, 'snooker', 2);
    await store.savePractice(run(a.id, 2));
    clock.now += PRACTICE_SEED_TTL_MS;
    expect(await store.practiceSeedState(a.id, 'snooker', 1)).toBe('open');
    clock.now += 1;
    expect(await store.practiceSeedState(a.id, 'snooker', 1)).toBe('unknown');
    expect((await store.savePractice(run(a.id, 1)).catch((err: unknown) => err)) as PracticeSeedError).toMatchObject({ state: 'unknown' });
    // The next seed issued sweeps the expired ones.
    expect(await count('practice_seeds')).toBe(2);
    await store.issuePracticeSeed(a.id, 'snooker', 3);
    expect(await count('practice_seeds')).toBe(1);
    expect(await count('practice_runs')).toBe(1); // the run stays
    clock.now += PRACTICE_SEED_TTL_MS + 1;
    expect(await store.sweepPracticeSeeds()).toBe(1);
    expect(await count('practice_seeds')).toBe(0);
  });

  it(`keeps at most ${PRACTICE_OPEN_SEEDS} unused practice seeds per player: a new one retires the oldest`, async () => {
    const { store, a, b } = await fresh();
    const n = PRACTICE_OPEN_SEEDS + 5;
    const kindOf = (s: number) => (s % 2 ? 'snooker' : 'nineball');
    for (let s = 1; s <= n; s++) await store.issuePracticeSeed(a.id, kindOf(s), s);
    await store.issuePracticeSeed(b.id, 'snooker', 1);
    const states = await Promise.all(Array.from({ length: n }, (_, i) => store.practiceSeedState(a.id, kindOf(i + 1), i + 1)));
    expect(states.flatMap((s, i) => (s === 'open' ? [i + 1] : []))).toEqual(Array.from({ length: PRACTICE_OPEN_SEEDS }, (_, i) => n - PRACTICE_OPEN_SEEDS + 1 + i));
    expect(await store.practiceSeedState(b.id, 'snooker', 1)).toBe('open'); // another player's are theirs
  });

  it('keeps one practice record per player, kind and type: the best, the first to reach it among equals (property)', async () => {
    const { store } = await fresh();
    let round = 0;
    await fc.assert(
      fc.asyncProperty(fc.array(fc.record({ who: fc.integer({ min: 0, max: 2 }), better: fc.integer({ min: -20, max: 20 }), kind: fc.constantFrom('snooker', 'nineball') }), { maxLength: 25 }), async (runs) => {
        // Fresh players each round, in the one store.
        round++;
        const players: PlayerRow[] = [];
        for (let i = 0; i < 3; i++) players.push(await store.createPlayer(`P${round}-${i}`, hash(0).fill(round % 256, 0, 1).fill(i + 1, 1, 2).fill(Math.floor(round / 256), 2, 3)));
        const best = new Map<string, { better: number; id: number }>();
        for (const [i, r] of runs.entries()) {
          const p = players[r.who]!.id;
          await store.issuePracticeSeed(p, r.kind, i);
          const { id, standing } = await store.savePractice(run(p, i, r.better, r.kind));
          const key = `${p}/${r.kind}`;
          const was = best.get(key);
          expect(standing).toEqual([was === undefined || r.better > was.better]);
          if (standing[0]) best.set(key, { better: r.better, id });
        }
        const mine = new Set(players.map((p) => p.id));
        for (const kind of ['snooker', 'nineball']) {
          const board = (await store.records(kind, 10_000, 0, 'practice')).filter((e) => mine.has(e.playerId));
          expect(board.map((e) => `${e.playerId}/${kind}`).sort()).toEqual([...best.keys()].filter((k) => k.endsWith(`/${kind}`)).sort());
          for (const e of board) expect({ better: e.value, id: e.practiceId }).toEqual(best.get(`${e.playerId}/${kind}`));
        }
      }),
      { numRuns: 15 },
    );
  });

  // Operations.

  it('proves a write, fails the proof while another holds the lock past the wait, and says its schema version', async () => {
    const { store, holdHealthLock } = await fresh();
    await expect(store.probeWrite(100)).resolves.toBeUndefined();
    await expect(store.probeWrite(0)).resolves.toBeUndefined();
    const release = await holdHealthLock();
    const t = performance.now();
    try {
      await expect(store.probeWrite(200)).rejects.toThrow();
    } finally {
      await release();
    }
    const waited = performance.now() - t;
    expect(waited).toBeGreaterThanOrEqual(150);
    expect(waited).toBeLessThan(5000);
    await expect(store.probeWrite(100)).resolves.toBeUndefined();
    expect(await store.schemaVersion()).toBe(SCHEMA);
  });
}
