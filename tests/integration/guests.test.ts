// Guests against the real server (a child process, a real SQLite file, real sockets; issue 36,
// findings 1 and 13): a nameless hello is welcomed even when a million old-style guest names are
// taken, new players are limited per address, guests who never played are pruned from the start,
// and lookalike or blank names are refused.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import { openDatabase } from '../../server/database.ts';
import type { ServerMessage } from '../../shared/protocol/index.ts';
import { wsUrl } from '../support/game-clients.ts';
import { ROOT, startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

const MIGRATIONS = join(ROOT, 'migrations');
const DAY = 86_400_000;

let server: ServerProcess | undefined;
const clients: ProtocolClient[] = [];
afterEach(async () => {
  await Promise.all(clients.splice(0).map((c) => c.close(500)));
  // A server stuck in a loop ignores SIGTERM.
  await server?.stop('SIGKILL');
  server = undefined;
});

/** Connects and sends a hello; resolves with the answer, or rejects after `timeoutMs`. */
async function hello(url: string, msg: { name?: string; token?: string } = {}, timeoutMs = 10_000): Promise<ServerMessage> {
  const client = await ProtocolClient.connect(wsUrl(url));
  clients.push(client);
  const id = client.newId();
  const answer = client.waitFor((m) => m.re === id, timeoutMs);
  client.send({ type: 'hello', ...msg, id });
  return answer;
}

/** A migrated database file with rows put straight in, the way an older server left them. */
function database(fill: (db: ReturnType<typeof openDatabase>['db']) => void): string {
  const dbPath = join(tempDir('baize-guests-'), 'baize.db');
  const { db } = openDatabase(dbPath, MIGRATIONS);
  fill(db);
  db.close();
  return dbPath;
}

describe('guests on the real server', () => {
  it('welcome a nameless hello promptly when a million old-style guest names are taken', async () => {
    const dbPath = database((db) => {
      const insert = db.prepare('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, ?)');
      const hash = Buffer.alloc(32);
      const now = Date.now();
      db.transaction(() => {
        for (let i = 0; i < 1_000_000; i++) {
          hash.writeUInt32LE(i, 0);
          insert.run(`Guest-${i}`, hash, now);
        }
      })();
    });
    server = await startServerProcess({ BAIZE_DB: dbPath });
    const welcome = await hello(server.url);
    expect(welcome).toMatchObject({ type: 'welcome', player: { name: expect.stringMatching(/^Guest-[A-Z2-9]{8}$/) } });
    // And the next one too: the server was not left busy.
    expect(await hello(server.url)).toMatchObject({ type: 'welcome' });
  }, 120_000);

  it('limit new players from one address, and tell them when to try again', async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir('baize-guests-'), 'baize.db'), BAIZE_GUESTS_PER_ADDRESS: '2' });
    const first = await hello(server.url);
    expect(await hello(server.url, { name: 'Ann' })).toMatchObject({ type: 'welcome' });
    const refused = await hello(server.url);
    expect(refused).toMatchObject({ type: 'error', code: 'too-many-guests' });
    expect(refused.type === 'error' && refused.message).toMatch(/try again in 30 minutes/);
    // A player coming back with a token is not a new one.
    expect(await hello(server.url, { token: first.type === 'welcome' ? first.token : '' })).toMatchObject({ type: 'welcome' });
  });

  it('refuse lookalike and blank-looking names over the wire', async () => {
    server = await startServerProcess({ BAIZE_DB: join(tempDir('baize-guests-'), 'baize.db') });
    expect(await hello(server.url, { name: 'Admin' })).toMatchObject({ type: 'welcome' });
    expect(await hello(server.url, { name: '\u0410dmin' })).toMatchObject({ type: 'error', code: 'name-taken' });
    expect(await hello(server.url, { name: 'ádmin' })).toMatchObject({ type: 'welcome' });
    expect(await hello(server.url, { name: 'ÁDMIN' })).toMatchObject({ type: 'error', code: 'name-taken' });
    for (const name of ['\u3164', '\u2800', '\u0301\u0301']) {
      const m = await hello(server.url, { name });
      expect(m, JSON.stringify(name)).toMatchObject({ type: 'error', code: 'bad-name' });
      expect(m.type === 'error' && m.message).toMatch(/visible character/);
    }
  });

  it('delete guests who never played and were last seen long ago, from the start', async () => {
    const long = Date.now() - 40 * DAY;
    const dbPath = database((db) => {
      const insert = db.prepare('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, ?)');
      insert.run('Gone', Buffer.alloc(32, 1), long);
      const host = Number(insert.run('Host', Buffer.alloc(32, 2), long).lastInsertRowid);
      insert.run('Recent', Buffer.alloc(32, 3), Date.now() - DAY);
      db.prepare("INSERT INTO rooms (id, kind, race_to, private, shot_clock, created_by, created_at, status, state, updated_at) VALUES ('r1', 'nineball', 1, 0, 0, ?, ?, 'closed', '{}', ?)").run(
        host,
        long,
        long,
      );
    });
    server = await startServerProcess({ BAIZE_DB: dbPath });
    // The name of the one deleted is free again once the first pass has run (the first tick).
    const deadline = Date.now() + 10_000;
    let answer: ServerMessage;
    do {
      await new Promise((r) => setTimeout(r, 200));
      answer = await hello(server.url, { name: 'Gone' });
    } while (answer.type === 'error' && Date.now() < deadline);
    expect(answer).toMatchObject({ type: 'welcome' });
    expect(await hello(server.url, { name: 'Host' })).toMatchObject({ type: 'error', code: 'name-taken' });
    expect(await hello(server.url, { name: 'Recent' })).toMatchObject({ type: 'error', code: 'name-taken' });
  });
});
