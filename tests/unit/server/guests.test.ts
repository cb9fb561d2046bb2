// Guests (issue 36, findings 1 and 13): new players limited per address, players who never played
// deleted some days after they were last seen, and name keys given to players from before them.
// The game service in-process over a real SQLite file, with a clock the test moves.
import Database from 'better-sqlite3';
import { copyFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { openDatabase } from '../../../server/database.ts';
import { addressKey } from '../../../server/address.ts';
import { GuestLimit } from '../../../server/game/guest-limit.ts';
import { listMigrations } from '../../../server/migrate.ts';
import { hashToken } from '../../../server/tokens.ts';
import type { ServerMessage } from '../../../shared/protocol/index.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';
import { last, openHarness, type Harness } from '../../support/service-harness.ts';

const DAY = 86_400_000;
const MINUTE = 60_000;

let h: Harness | undefined;
afterEach(async () => {
  h?.close();
  h = undefined;
});

/** The welcome or error a hello got (a player with seats also gets their rooms after it). */
const reply = (got: Map<number, ServerMessage[]>, conn: number): ServerMessage => got.get(conn)!.find((m) => m.type !== 'room')!;

async function hello(h: Harness, conn: number, address: string, extra: { name?: string; token?: string } = {}): Promise<ServerMessage> {
  h.open(conn, address);
  return reply(await h.send(conn, { type: 'hello', ...extra }), conn);
}

describe('new players per address', () => {
  it('are limited to the configured number an hour, saying when to try again', async () => {
    h = await openHarness({ service: { guestsPerAddress: 3 } });
    const home = '203.0.113.7';
    expect(await hello(h, 1, home)).toMatchObject({ type: 'welcome' });
    const ann = await hello(h, 2, home, { name: 'Ann' });
    expect(await hello(h, 3, home)).toMatchObject({ type: 'welcome' });
    const refused = await hello(h, 4, home, { name: 'Dee' });
    expect(refused).toMatchObject({ type: 'error', code: 'too-many-guests' });
    expect(refused.type === 'error' && refused.message).toMatch(/at most 3 an hour\): try again in 20 minutes/);
    // Refused names do not use up the address's share; players with a token are not new.
    expect(await hello(h, 5, home, { name: '\u3164' })).toMatchObject({ type: 'error', code: 'bad-name' });
    expect(await hello(h, 6, home, { name: 'ANN' })).toMatchObject({ type: 'error', code: 'name-taken' });
    expect(await hello(h, 7, home, { token: ann.type === 'welcome' ? ann.token : '' })).toMatchObject({ type: 'welcome', player: { name: 'Ann' } });
    // Another address has its own share.
    expect(await hello(h, 8, '198.51.100.1')).toMatchObject({ type: 'welcome' });
    // The share comes back at 3 an hour: one after 20 minutes.
    h.clock += 20 * MINUTE;
    expect(await hello(h, 9, home)).toMatchObject({ type: 'welcome' });
    expect(await hello(h, 10, home)).toMatchObject({ type: 'error', code: 'too-many-guests' });
  });

  it('count an IPv6 /64 network as one address, and IPv4-mapped addresses as IPv4', async () => {
    h = await openHarness({ service: { guestsPerAddress: 1 } });
    expect(await hello(h, 1, '2001:db8:1:2::1')).toMatchObject({ type: 'welcome' });
    expect(await hello(h, 2, '2001:db8:1:2:ffff::9')).toMatchObject({ type: 'error', code: 'too-many-guests' });
    expect(await hello(h, 3, '2001:db8:1:3::1')).toMatchObject({ type: 'welcome' });
    expect(await hello(h, 4, '192.0.2.1')).toMatchObject({ type: 'welcome' });
    expect(await hello(h, 5, '::ffff:192.0.2.1')).toMatchObject({ type: 'error', code: 'too-many-guests' });
    expect(addressKey('2001:0db8:0001:0002:0000:0000:0000:0001')).toBe(addressKey('2001:db8:1:2::'));
    expect(addressKey('::1')).toBe('0:0:0:0::/64');
  });

  it('keep no memory of addresses whose share is whole again, and at most a bounded number', async () => {
    const limit = new GuestLimit(2, 1000);
    const t0 = 1_800_000_000_000;
    for (let i = 0; i < 5000; i++) {
      const address = `10.0.${i >> 8}.${i & 255}`;
      expect(limit.take(address, t0)).toBe(0);
      expect(limit.take(address, t0)).toBe(0);
    }
    expect(limit.size).toBe(1000);
    limit.sweep(t0 + 30 * MINUTE); // half an hour: one of two back, not whole
    expect(limit.size).toBe(1000);
    limit.sweep(t0 + 60 * MINUTE);
    expect(limit.size).toBe(0);
  });

  it('are not limited when the service is not given a limit', async () => {
    h = await openHarness();
    for (let c = 1; c <= 50; c++) expect(await hello(h, c, '203.0.113.7')).toMatchObject({ type: 'welcome' });
  });
});

describe('players who never played', () => {
  /** Counts rows through a second connection to the same file. */
  const count = async (h: Harness, sql: string): Promise<number> => {
    const db = new Database(h.dbPath, { readonly: true });
    try {
      return (db.prepare(sql).get() as { n: number }).n;
    } finally {
      db.close();
    }
  };

  it('are deleted once not seen for the configured days; anyone who played, created or is here is kept', async () => {
    h = await openHarness({ service: { guestKeepMs: 30 * DAY } });
    const t0 = h.clock;
    const welcome = async (conn: number, name: string) => {
      await h!.send(conn, { type: 'hello', name });
      return last(h!, conn, 'welcome');
    };
    const idle = await welcome(1, 'Idle');
    const creator = await welcome(2, 'Creator');
    await h.send(2, { type: 'create', kind: 'nineball' });
    const host = await welcome(3, 'Host');
    const guest = await welcome(4, 'Guest');
    await h.send(3, { type: 'create', kind: 'eightball' });
    await h.send(4, { type: 'join', room: last(h, 3, 'room').room.id });
    const practiser = await welcome(5, 'Practiser');
    await h.store.issuePracticeSeed(Number(practiser.player.id), 'nineball', 1);
    await h.store.savePractice({ player: Number(practiser.player.id), kind: 'nineball', seed: 1, shots: '[]', score: 0, records: [] });
    const returner = await welcome(6, 'Returner');
    const here = await welcome(7, 'Here');
    for (const c of [1, 2, 3, 4, 5, 6]) await h.drop(c);
    h.clock = t0 + 20 * DAY;
    expect(reply(await h.send(8, { type: 'hello', token: returner.token }), 8)).toMatchObject({ type: 'welcome' });
    await h.drop(8);
    h.clock = t0 + 31 * DAY;
    await h.tick();

    const back = async (token: string, conn: number) => reply(await h!.send(conn, { type: 'hello', token }), conn);
    expect(await back(idle.token, 20)).toMatchObject({ type: 'error', code: 'bad-token' });
    for (const [i, p] of [creator, host, guest, practiser, returner, here].entries()) {
      expect(await back(p.token, 21 + i), p.player.name).toMatchObject({ type: 'welcome', player: p.player });
    }
    // Its name is free again.
    expect(reply(await h.send(30, { type: 'hello', name: 'Idle' }), 30)).toMatchObject({ type: 'welcome' });
  });

  it('are deleted in bounded batches from the first tick on, and kept when another table still refers to them', async () => {
    h = await openHarness({ service: { guestKeepMs: 30 * DAY } });
    for (let i = 0; i < 1200; i++) await h.store.createPlayer(`Old-${i}`, hashToken(`old-${i}`));
    // A table this release does not know about refers to one of them: the foreign key keeps it.
    const db = new Database(h.dbPath);
    db.exec('CREATE TABLE elsewhere (player_id INTEGER NOT NULL REFERENCES players (id))');
    db.prepare("INSERT INTO elsewhere VALUES ((SELECT id FROM players WHERE name = 'Old-7'))").run();
    db.close();
    h.clock += 31 * DAY;
    await h.tick();
    const after1 = await count(h, 'SELECT count(*) AS n FROM players');
    expect(after1).toBeGreaterThanOrEqual(700);
    expect(after1).toBeLessThan(1200);
    for (let i = 0; i < 5; i++) await h.tick();
    expect(await count(h, 'SELECT count(*) AS n FROM players')).toBe(1);
    expect(await h.store.nameOwner('Old-7')).toBeDefined();
  });
});

describe('players from before the name keys', () => {
  it('get keys at start-up: the older of two lookalikes keeps the name, the later one keeps playing', async () => {
    // A database at schema 004, with names that were unique then (case folded for ASCII only).
    const dir = tempDir('baize-legacy-');
    for (const m of listMigrations(join(ROOT, 'migrations')).filter((m) => m.version <= 4)) copyFileSync(m.path, join(dir, m.file));
    const dbPath = join(tempDir('baize-legacy-db-'), 'baize.db');
    const old = openDatabase(dbPath, dir).db;
    const insert = old.prepare('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, ?)');
    const legacy = ['Ádmin', 'ádmin', '\u0410dmin', 'Admin', 'Bob'];
    legacy.forEach((name, i) => insert.run(name, hashToken(`token-${i}`), 1_700_000_000_000 + i));
    old.close();

    h = await openHarness({ dbPath });
    // Everyone is still who they were.
    for (const [i, name] of legacy.entries()) expect(reply(await h!.send(i + 1, { type: 'hello', token: `token-${i}` }), i + 1)).toMatchObject({ type: 'welcome', player: { name } });
    // Lookalikes of the older players' names are taken.
    for (const [i, name] of ['ÁDMIN', 'ADMIN', 'admin', 'BOB'].entries()) {
      expect(reply(await h.send(10 + i, { type: 'hello', name }), 10 + i), name).toMatchObject({ type: 'error', code: 'name-taken' });
    }
    // The later "ádmin" (conn 2) may not move onto the older one's key, but may take a new name;
    // the older Cyrillic "Аdmin" (conn 3) may change the case of its own.
    expect(reply(await h.send(2, { type: 'rename', name: 'ÁDMIN' }), 2)).toMatchObject({ type: 'error', code: 'name-taken' });
    expect(reply(await h.send(2, { type: 'rename', name: 'Carol' }), 2)).toMatchObject({ type: 'player', player: { name: 'Carol' } });
    expect(reply(await h.send(3, { type: 'rename', name: '\u0410DMIN' }), 3)).toMatchObject({ type: 'player', player: { name: '\u0410DMIN' } });
  });
});
