// The store's practice seeds and standing practice records, over a real SQLite file with a test
// clock: a seed is used once, within its lifetime, by its own player for its own kind; expired and
// surplus seeds go; a player's practice record of a kind and type is one, their best.
import Database from 'better-sqlite3';
import fc from 'fast-check';
import { copyFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { openDatabase } from '../../../server/database.ts';
import { listMigrations, migrate } from '../../../server/migrate.ts';
import { PRACTICE_OPEN_SEEDS, PRACTICE_SEED_TTL_MS, PracticeSeedError, Store } from '../../../server/store/index.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';

const MIGRATIONS = join(ROOT, 'migrations');
const closers: (() => void)[] = [];
afterEach(() => closers.splice(0).forEach((c) => c()));

function open() {
  const { db } = openDatabase(join(tempDir('baize-practice-'), 'baize.db'), MIGRATIONS);
  closers.push(() => db.close());
  const clock = { now: 1_800_000_000_000 };
  const store = new Store(db, () => clock.now);
  const a = store.createPlayer('Ann', Buffer.alloc(32, 1));
  const b = store.createPlayer('Bob', Buffer.alloc(32, 2));
  const count = (table: string) => (db.prepare(`SELECT count(*) AS n FROM ${table}`).get() as { n: number }).n;
  return { db, store, clock, a, b, count };
}

const run = (player: number, seed: number, better = 10, kind = 'snooker') => ({
  player,
  kind,
  seed,
  shots: '[]',
  score: better,
  records: [{ what: 'break', player, value: better, better }],
});

describe('practice seeds in the store', () => {
  it('are used once, by their player, for their kind; a refused save writes nothing', () => {
    const { store, a, b, count } = open();
    expect(store.issuePracticeSeed(a.id, 'snooker', 42)).not.toBeNull();
    expect(store.issuePracticeSeed(a.id, 'snooker', 42)).toBeNull(); // held already: draw another
    expect(store.practiceSeedState(a.id, 'snooker', 42)).toBe('open');
    expect(store.practiceSeedState(b.id, 'snooker', 42)).toBe('unknown');
    expect(store.practiceSeedState(a.id, 'nineball', 42)).toBe('unknown');
    expect(() => store.savePractice(run(b.id, 42))).toThrow(PracticeSeedError);
    expect(() => store.savePractice(run(a.id, 42, 10, 'nineball'))).toThrow(PracticeSeedError);
    expect(count('practice_runs')).toBe(0);
    expect(count('records')).toBe(0);
    store.savePractice(run(a.id, 42));
    expect(store.practiceSeedState(a.id, 'snooker', 42)).toBe('used');
    const again = (() => {
      try {
        store.savePractice(run(a.id, 42, 99));
      } catch (err) {
        return err;
      }
    })();
    expect(again).toBeInstanceOf(PracticeSeedError);
    expect((again as PracticeSeedError).state).toBe('used');
    expect(count('practice_runs')).toBe(1);
    expect(store.records('snooker', 10, 0, 'practice').map((r) => r.value)).toEqual([10]);
  });

  it('expire after their lifetime, and are deleted then, used or not', () => {
    const { store, clock, a, count } = open();
    store.issuePracticeSeed(a.id, 'snooker', 1);
    store.issuePracticeSeed(a.id, 'snooker', 2);
    store.savePractice(run(a.id, 2));
    clock.now += PRACTICE_SEED_TTL_MS - 1;
    expect(store.practiceSeedState(a.id, 'snooker', 1)).toBe('open');
    clock.now += 1;
    expect(store.practiceSeedState(a.id, 'snooker', 1)).toBe('open');
    clock.now += 1;
    expect(store.practiceSeedState(a.id, 'snooker', 1)).toBe('unknown');
    expect(() => store.savePractice(run(a.id, 1))).toThrow(PracticeSeedError);
    // The next seed issued sweeps the expired ones.
    expect(count('practice_seeds')).toBe(2);
    store.issuePracticeSeed(a.id, 'snooker', 3);
    expect(count('practice_seeds')).toBe(1);
    expect(count('practice_runs')).toBe(1); // the run stays
  });

  it(`keep at most ${PRACTICE_OPEN_SEEDS} unused per player: a new one retires the oldest`, () => {
    const { store, a, b } = open();
    const n = PRACTICE_OPEN_SEEDS + 5;
    for (let s = 1; s <= n; s++) store.issuePracticeSeed(a.id, s % 2 ? 'snooker' : 'nineball', s);
    store.issuePracticeSeed(b.id, 'snooker', 1);
    const open_ = Array.from({ length: n }, (_, i) => i + 1).filter((s) => store.practiceSeedState(a.id, s % 2 ? 'snooker' : 'nineball', s) === 'open');
    expect(open_).toEqual(Array.from({ length: PRACTICE_OPEN_SEEDS }, (_, i) => n - PRACTICE_OPEN_SEEDS + 1 + i));
    expect(store.practiceSeedState(b.id, 'snooker', 1)).toBe('open'); // another player's are theirs
  });
});

describe('practice records in the store', () => {
  it('stand one per player, kind and type: the best, the first to reach it among equals (property)', () => {
    fc.assert(
      fc.property(fc.array(fc.record({ who: fc.integer({ min: 0, max: 2 }), better: fc.integer({ min: -20, max: 20 }), kind: fc.constantFrom('snooker', 'nineball') }), { maxLength: 40 }), (runs) => {
        const { store } = open();
        const players = [store.createPlayer('P0', Buffer.alloc(32, 10)), store.createPlayer('P1', Buffer.alloc(32, 11)), store.createPlayer('P2', Buffer.alloc(32, 12))];
        const best = new Map<string, { better: number; id: number }>();
        runs.forEach((r, i) => {
          const p = players[r.who]!.id;
          store.issuePracticeSeed(p, r.kind, i);
          const { id, standing } = store.savePractice(run(p, i, r.better, r.kind));
          const key = `${p}/${r.kind}`;
          const was = best.get(key);
          expect(standing).toEqual([was === undefined || r.better > was.better]);
          if (standing[0]) best.set(key, { better: r.better, id });
        });
        for (const kind of ['snooker', 'nineball']) {
          const board = store.records(kind, 100, 0, 'practice');
          expect(board.map((e) => `${e.playerId}/${kind}`).sort()).toEqual([...best.keys()].filter((k) => k.endsWith(`/${kind}`)).sort());
          for (const e of board) expect({ better: e.value, id: e.practiceId }).toEqual(best.get(`${e.playerId}/${kind}`));
          expect(store.records(kind, 100, 0, 'match')).toEqual([]);
        }
      }),
      { numRuns: 30 },
    );
  });

  it('from before this change keep each player\'s best of a kind and type when migrated; the runs stay', () => {
    const dir = tempDir('baize-migrations-');
    for (const m of listMigrations(MIGRATIONS).filter((m) => m.version <= 4)) copyFileSync(m.path, join(dir, m.file));
    const path = join(tempDir(), 'old.db');
    const db = new Database(path);
    closers.push(() => db.close());
    migrate(db, dir);
    db.prepare("INSERT INTO players (id, name, token_hash, created_at) VALUES (1, 'Ann', ?, 0), (2, 'Bob', ?, 0)").run(Buffer.alloc(32, 1), Buffer.alloc(32, 2));
    const runInsert = db.prepare("INSERT INTO practice_runs (id, player_id, kind, seed, shots, score, created_at) VALUES (?, ?, ?, 7, '[]', 0, 0)");
    const recInsert = db.prepare('INSERT INTO records (id, kind, what, player_id, value, better, practice_id, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, 0)');
    const rows: [number, string, string, number, number][] = [
      // id, kind, what, player, better
      [1, 'snooker', 'break', 1, 30],
      [2, 'snooker', 'break', 1, 91],
      [3, 'snooker', 'break', 1, 91],
      [4, 'snooker', 'break', 2, 12],
      [5, 'nineball', 'break-and-run', 1, -9],
      [6, 'nineball', 'break-and-run', 1, -6],
      [7, 'threecushion', 'run', 1, 4],
    ];
    for (const [id, kind, what, player, better] of rows) {
      runInsert.run(id, player, kind);
      recInsert.run(id, kind, what, player, Math.abs(better), better, id);
    }
    migrate(db, MIGRATIONS);
    expect(db.prepare('SELECT id FROM records ORDER BY id').all()).toEqual([2, 4, 6, 7].map((id) => ({ id })));
    expect((db.prepare('SELECT count(*) AS n FROM practice_runs').get() as { n: number }).n).toBe(rows.length);
    expect(() => recInsert.run(8, 'snooker', 'break', 2, 13, 13, 4)).toThrow(/UNIQUE/);
  });
});
