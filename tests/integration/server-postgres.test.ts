// The real server process on PostgreSQL (BAIZE_DATABASE_URL, a server the test starts on
// 127.0.0.1): two players over real sockets play a whole game of nine-ball; its result (and
// ratings, when rated) are in PostgreSQL once; after kill -9 and a restart on the same database
// the result is still there once and an unfinished room comes back as it was. Skips without
// PostgreSQL's binaries, unless BAIZE_REQUIRE_POSTGRES=1.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import pg from 'pg';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { ask, connect, playToEnd, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

describe.skipIf(!postgresAvailable())('the game server on PostgreSQL', () => {
  let db: PostgresServer;
  let server: ServerProcess | undefined;
  const seats: Seat[] = [];
  beforeAll(async () => {
    db = await startPostgres();
  }, 60_000);
  afterEach(async () => {
    await Promise.all(seats.splice(0).map((s) => s.client.close(200)));
    await server?.stop('SIGKILL');
    server = undefined;
  });
  afterAll(async () => {
    await db?.stop();
  });

  async function query<R extends pg.QueryResultRow>(url: string, text: string): Promise<R[]> {
    const c = new pg.Client({ connectionString: url });
    await c.connect();
    try {
      return (await c.query<R>(text)).rows;
    } finally {
      await c.end();
    }
  }

  it('plays a whole game, keeps its result once, and brings an unfinished room back after kill -9', async () => {
    const url = await db.database('served');
    const file = join(tempDir(), 'never.db');
    // Rated after a real game whatever its length: no minimum time of play.
    const env = { BAIZE_DATABASE_URL: url, BAIZE_DB: file, BAIZE_RATED_MIN_PLAY_S: '0' };
    server = await startServerProcess(env);
    const ws = wsUrl(server.url);
    const seat = async (hello: { name?: string; token?: string }) => {
      const s = await connect(ws, hello);
      seats.push(s);
      return s;
    };
    const health = (await (await fetch(`${server.url}/healthz`)).json()) as { schema: number };
    expect(health.schema).toBe(10);

    const a = await seat({ name: 'Pia' });
    const b = await seat({ name: 'Quin' });
    const created = await ask(a, { type: 'create', kind: 'nineball' });
    if (created.type !== 'room') throw new Error(JSON.stringify(created));
    const room = created.room.id;
    await ask(b, { type: 'join', room });
    await until(a, room, (r) => r.status === 'playing');
    const shots = await playToEnd(a, b, room, 2000);
    const final = a.rooms.get(room)!;
    expect(final.status).toBe('over');
    expect(final.view!.winner).toBe(final.game!.winner);
    expect(shots).toBeGreaterThan(0);
    const matchId = final.view!.match!;
    const winner = Number(final.view!.winner);
    const loser = Number(final.view!.players.find((p) => p.id !== final.view!.winner)!.id);

    // Another game left unfinished: a table with one shot played.
    const c = await seat({ name: 'Rue' });
    const d = await seat({ name: 'Sol' });
    const other = await ask(c, { type: 'create', kind: 'eightball' });
    if (other.type !== 'room') throw new Error(JSON.stringify(other));
    const open = other.room.id;
    await ask(d, { type: 'join', room: open });
    await until(c, open, (r) => r.status === 'playing');
    await playTurn(c, open);
    await until(d, open, (r) => r.stateId === 2);
    const before = c.rooms.get(open)!;

    const results = () => query<{ match_id: number; winner: number; loser: number; how: string; rated: number }>(url, 'SELECT match_id::int, winner::int, loser::int, how, rated FROM results');
    const stored = await results();
    expect(stored).toEqual([{ match_id: matchId, winner, loser, how: 'played', rated: final.view!.rated ? 1 : 0 }]);
    const ratings = () => query<{ player_id: number; games: number; wins: number }>(url, "SELECT player_id::int, games, wins FROM ratings WHERE kind = 'nineball' ORDER BY wins DESC");
    // Rated: each player's rating once; unrated (too few shots): none.
    expect(await ratings()).toEqual(final.view!.rated ? [{ player_id: winner, games: 1, wins: 1 }, { player_id: loser, games: 1, wins: 0 }] : []);
    // The match's log has every shot once, in order.
    const actions = await query<{ seq: number }>(url, `SELECT seq FROM match_actions WHERE match_id = ${matchId} ORDER BY seq`);
    expect(actions.map((x) => x.seq)).toEqual(Array.from({ length: actions.length }, (_, i) => i + 2));
    expect(existsSync(file)).toBe(false);

    expect(await server.stop('SIGKILL')).toBeNull();
    await Promise.all(seats.map((s) => s.client.closed));
    seats.splice(0);
    server = await startServerProcess(env);
    const ws2 = wsUrl(server.url);
    const c2 = await connect(ws2, { token: c.token });
    const d2 = await connect(ws2, { token: d.token });
    const a2 = await connect(ws2, { token: a.token });
    seats.push(c2, d2, a2);
    await until(c2, open, (r) => r.stateId === before.stateId);
    expect(c2.rooms.get(open)).toMatchObject({ status: 'playing', stateId: before.stateId, game: before.game });
    // The finished room too, with its result's rating line; the result is stored once still.
    await until(a2, room, (r) => r.status === 'over');
    expect(a2.rooms.get(room)!.view).toMatchObject({ winner: final.view!.winner, rated: final.view!.rated });
    expect(await results()).toEqual(stored);
    // And play goes on in the unfinished room.
    const onTurn = before.game!.turn === c.player.id ? c2 : d2;
    const next = await playTurn(onTurn, open);
    expect(next.stateId).toBe(before.stateId + 1);
  }, 120_000);
});
