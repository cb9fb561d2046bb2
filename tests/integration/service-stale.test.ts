// Two game services over one database, as two processes would be (a SQLite file; a real
// PostgreSQL): both hold the same room. A move one commits makes the other's move at the same
// stateId fail with stale-state and change nothing; that service then holds the committed state
// and plays on from it. Skips PostgreSQL without its binaries, unless BAIZE_REQUIRE_POSTGRES=1.
import { join } from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import type { ServerMessage } from '../../shared/protocol/index.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';
import { tempDir } from '../support/server-process.ts';
import { last, openHarness, type Harness, type HarnessOptions } from '../support/service-harness.ts';

const errorOf = (msgs: ServerMessage[] | undefined) => msgs?.find((m) => m.type === 'error') as Extract<ServerMessage, { type: 'error' }> | undefined;
const shot = (speed: number) => ({ ball: 'cue', heading: 0, speed, side: 0, top: 0 });

function staleCases(database: () => Promise<HarnessOptions>): void {
  const open: Harness[] = [];
  afterEach(async () => {
    for (const h of open.splice(0)) await h.close();
  });

  it('refuses the second of two moves at one stateId with stale-state, writes nothing of it, and shows the committed state', async () => {
    const where = await database();
    const one = await openHarness(where);
    open.push(one);
    await one.send(1, { type: 'hello', name: 'Ann' });
    await one.send(2, { type: 'hello', name: 'Bob' });
    const tokens = [last(one, 1, 'welcome').token, last(one, 2, 'welcome').token];
    await one.send(1, { type: 'create', kind: 'nineball' });
    const id = last(one, 1, 'room').room.id;
    await one.send(2, { type: 'join', room: id });
    const room = last(one, 2, 'room').room;
    expect(room).toMatchObject({ status: 'playing', stateId: 1 });

    // A second service over the same database brings the room back, and the players say hello there too.
    const two = await openHarness(where);
    open.push(two);
    await two.send(1, { type: 'hello', token: tokens[0]! });
    await two.send(2, { type: 'hello', token: tokens[1]! });
    expect(last(two, 1, 'room').room).toMatchObject({ id, stateId: 1 });

    // The first service commits Ann's break; the second, still at stateId 1, is refused.
    await one.send(1, { type: 'shot', room: id, stateId: 1, shot: shot(6) });
    const committed = last(one, 1, 'shot');
    expect(committed.stateId).toBe(2);
    const refused = await two.send(1, { type: 'shot', id: 7, room: id, stateId: 1, shot: shot(3) });
    expect(errorOf(refused.get(1))).toMatchObject({ re: 7, code: 'stale-state' });
    expect(errorOf(refused.get(1))!.message).toMatch(/changed elsewhere.*stateId 2/);
    // Nothing of it was written: one shot in the log, the room as the first service left it.
    const actions = await two.store.matchActions(room.match!);
    expect(actions.map((a) => a.seq)).toEqual([2]);
    expect(JSON.parse((await two.store.room(id))!.state)).toMatchObject({ stateId: 2, game: committed.game });
    // Both players on the second service are shown the committed state.
    for (const conn of [1, 2]) expect(last(two, conn, 'room').room).toMatchObject({ id, stateId: 2, game: committed.game });

    // The second service plays on from it; now the first is the stale one.
    const turn = committed.game.turn === room.players[0]!.id ? 1 : 2;
    await two.send(turn, { type: 'shot', room: id, stateId: 2, shot: shot(3) });
    expect(last(two, turn, 'shot').stateId).toBe(3);
    expect(errorOf((await one.send(turn, { type: 'shot', room: id, stateId: 2, shot: shot(4) })).get(turn))?.code).toBe('stale-state');
    expect(last(one, turn, 'room').room.stateId).toBe(3);
    expect((await one.store.matchActions(room.match!)).map((a) => a.seq)).toEqual([2, 3]);
  });
}

describe('two game services over one SQLite file', () => {
  staleCases(async () => ({ dbPath: join(tempDir('baize-stale-'), 'baize.db') }));
});

describe.skipIf(!postgresAvailable())('two game services over one PostgreSQL database', () => {
  let server: PostgresServer;
  let made = 0;
  beforeAll(async () => {
    server = await startPostgres();
  }, 60_000);
  afterAll(async () => {
    await server?.stop();
  });
  staleCases(async () => ({ databaseUrl: await server.database(`stale_${++made}`) }));
});
