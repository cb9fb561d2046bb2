// Three real server processes over one real Redis and one real PostgreSQL (both started by the
// tests on 127.0.0.1): players on different processes play whole games of every kind while a
// spectator on the third sees every shot; every process lists the same lobby; the room's owner is
// killed (-9) mid-game and play goes on through the others, the replay giving the broadcast
// hashes; results and ratings are written once; the per-player room limit holds across processes.
// Skips without redis-server or PostgreSQL unless BAIZE_REQUIRE_REDIS / BAIZE_REQUIRE_POSTGRES.
import pg from 'pg';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { connectRedis } from '../../server/cluster/index.ts';
import type { GameKindName, ServerMessage } from '../../shared/protocol/index.ts';
import { achievements, replayMatch, type MatchRecord } from '../../shared/rules/index.ts';
import { ask, connect, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';
import { redisAvailable, startRedis, type RedisServer } from '../support/redis.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

type Shot = Extract<ServerMessage, { type: 'shot' }>;
const shotsIn = (seat: Seat, room: string): Shot[] => seat.log.filter((m): m is Shot => m.type === 'shot' && m.room === room);

/** The player on turn's shot, tried again while the room's owner is being replaced ('unavailable'). */
async function shoot(seat: Seat, room: string, withinMs = 15_000): Promise<Shot> {
  const end = Date.now() + withinMs;
  for (;;) {
    try {
      return await playTurn(seat, room);
    } catch (err) {
      if (!String(err).includes('"unavailable"') || Date.now() > end) throw err;
      await new Promise((r) => setTimeout(r, 100));
    }
  }
}

/** Plays a room's game to its end between two seats, each on its own process. */
async function playOut(a: Seat, b: Seat, room: string, onShot?: (n: number) => Promise<void>): Promise<number> {
  let shots = 0;
  for (; shots < 2000; shots++) {
    const r = a.rooms.get(room)!;
    if (r.status !== 'playing') break;
    const seat = r.game!.turn === a.player.id ? a : b;
    await until(seat, room, (x) => x.stateId === r.stateId);
    const shot = await shoot(seat, room);
    await until(a, room, (x) => x.stateId >= shot.stateId && (x.status !== 'playing' || x.game?.winner === null));
    await onShot?.(shots + 1);
  }
  return shots;
}

describe.runIf(redisAvailable() && postgresAvailable())('three processes over Redis and PostgreSQL', () => {
  let redis: RedisServer;
  let db: PostgresServer;
  let url: string;
  const procs: ServerProcess[] = [];
  const seats: Seat[] = [];

  const start = async (n: number) => {
    const env = { BAIZE_DATABASE_URL: url, BAIZE_REDIS_URL: redis.url, BAIZE_DB: `${tempDir()}/never.db`, BAIZE_RATED_MIN_PLAY_S: '0' };
    for (let i = 0; i < n; i++) procs.push(await startServerProcess({ ...env, BAIZE_PROCESS_ID: `p${procs.length + 1}` }));
  };
  const seat = async (proc: ServerProcess, hello: { name?: string; token?: string }) => {
    const s = await connect(wsUrl(proc.url), hello);
    seats.push(s);
    return s;
  };
  /** A room made by a new player on `makerOn` and joined by one on `joinerOn`: play has started. */
  const table = async (makerOn: ServerProcess, joinerOn: ServerProcess, kind: GameKindName, names: [string, string], raceTo?: number) => {
    const a = await seat(makerOn, { name: names[0] });
    const created = await ask(a, { type: 'create', kind, ...(raceTo === undefined ? {} : { raceTo }) });
    if (created.type !== 'room') throw new Error(JSON.stringify(created));
    const room = created.room.id;
    const b = await seat(joinerOn, { name: names[1] });
    await ask(b, { type: 'join', room });
    await until(a, room, (r) => r.status === 'playing');
    return { a, b, room };
  };
  const query = async <R extends pg.QueryResultRow>(text: string, values: unknown[] = []): Promise<R[]> => {
    const c = new pg.Client({ connectionString: url });
    await c.connect();
    try {
      return (await c.query<R>(text, values)).rows;
    } finally {
      await c.end();
    }
  };
  const lobbyIds = async (s: Seat): Promise<string[]> => {
    const m = await ask(s, { type: 'lobby' });
    if (m.type !== 'lobby') throw new Error(JSON.stringify(m));
    return m.rooms.map((r) => `${r.id}:${r.status}:${r.players.length}`).sort();
  };
  /** Every process's lobby, once they agree (the mirrors follow pub/sub). */
  const agreedLobby = async (watchers: Seat[], ok: (ids: string[]) => boolean): Promise<string[]> => {
    const end = Date.now() + 5000;
    for (;;) {
      const all = await Promise.all(watchers.map(lobbyIds));
      if (all.every((x) => JSON.stringify(x) === JSON.stringify(all[0])) && ok(all[0]!)) return all[0]!;
      if (Date.now() > end) throw new Error(`the lobbies differ: ${JSON.stringify(all)}`);
      await new Promise((r) => setTimeout(r, 50));
    }
  };

  beforeAll(async () => {
    [redis, db] = await Promise.all([startRedis(), startPostgres()]);
  }, 60_000);
  afterEach(async (ctx) => {
    // A failure shows what the processes logged.
    if (ctx.task.result?.state === 'fail') for (const p of procs) console.error(`${p.url}:\n${p.stderr()}`);
    await Promise.all(seats.splice(0).map((s) => s.client.close(200)));
    await Promise.all(procs.splice(0).map((p) => p.stop('SIGKILL')));
    // Each test starts from an empty Redis (its processes reuse the names p1, p2, p3).
    const c = await connectRedis(redis.url, 'test');
    await c.sendCommand(['FLUSHALL']);
    c.destroy();
  });
  afterAll(async () => {
    await Promise.all([redis?.stop(), db?.stop()]);
  });

  it('plays every kind across processes, a spectator on the third seeing every shot, the lobby the same everywhere', async () => {
    url = await db.database('kinds');
    await start(3);
    const kinds: GameKindName[] = ['nineball', 'eightball', 'snooker', 'threecushion'];
    const watchers = await Promise.all(procs.map((p, i) => seat(p, { name: `Lobby-${i + 1}` })));
    const tables = await Promise.all(
      kinds.map(async (kind, i) => {
        // The maker's process owns the room: each kind has its owner on another process.
        const [pa, pb, ps] = [procs[i % 3]!, procs[(i + 1) % 3]!, procs[(i + 2) % 3]!];
        const a = await seat(pa, { name: `A-${kind}` });
        const created = await ask(a, { type: 'create', kind, raceTo: 1 });
        if (created.type !== 'room') throw new Error(JSON.stringify(created));
        const room = created.room.id;
        const s = await seat(ps, { name: `S-${kind}` });
        const watched = await ask(s, { type: 'watch', room });
        if (watched.type !== 'room') throw new Error(JSON.stringify(watched));
        const b = await seat(pb, { name: `B-${kind}` });
        return { kind, room, a, b, s };
      }),
    );
    // Four waiting tables, listed alike by every process.
    const waiting = await agreedLobby(watchers, (ids) => ids.length === 4);
    expect(waiting.every((x) => x.endsWith(':waiting:1'))).toBe(true);
    for (const t of tables) expect(await ask(t.b, { type: 'join', room: t.room })).toMatchObject({ type: 'room' });
    for (const t of tables) await until(t.a, t.room, (r) => r.status === 'playing');
    await agreedLobby(watchers, (ids) => ids.length === 4 && ids.every((x) => x.endsWith(':playing:2')));

    await Promise.all(tables.map((t) => playOut(t.a, t.b, t.room)));
    for (const t of tables) {
      const final = t.a.rooms.get(t.room)!;
      expect(final.status).toBe('over');
      expect(final.view!.winner).toBe(final.game!.winner);
      await until(t.s, t.room, (r) => r.status === 'over');
      // Both players and the spectator saw the same shots; the replay gives their hashes.
      const seen = shotsIn(t.a, t.room).map((m) => m.outcome.hash);
      expect(seen.length).toBeGreaterThan(0);
      expect(shotsIn(t.b, t.room).map((m) => m.outcome.hash)).toEqual(seen);
      expect(shotsIn(t.s, t.room).map((m) => m.outcome.hash)).toEqual(seen);
      const record = (await (await fetch(`${procs[2]!.url}/api/matches/${final.view!.match}`)).json()) as MatchRecord;
      const replayed = replayMatch(record);
      expect(replayed.shots.map((x) => x.hash)).toEqual(seen);
      expect(replayed.game).toEqual(final.game);
      // The records the match set are those its replay shows, each written once.
      const stored = await query<{ player: string; value: number }>('SELECT player_id::text AS player, value FROM records WHERE match_id = $1 ORDER BY player_id, value', [final.view!.match]);
      const expected = achievements(record.start, replayed.games)
        .map((x) => ({ player: x.player, value: x.value }))
        .sort((x, y) => Number(x.player) - Number(y.player) || x.value - y.value);
      expect(stored).toEqual(expected);
    }
    // One result per match, and each rated one counted once in both players' ratings.
    const matches = tables.map((t) => t.a.rooms.get(t.room)!.view!.match!);
    const results = await query<{ match_id: number; rated: number }>('SELECT match_id::int, rated::int FROM results WHERE match_id = ANY($1) ORDER BY match_id', [matches]);
    expect(results.map((r) => r.match_id)).toEqual([...matches].sort((x, y) => x - y));
    const players = tables.flatMap((t) => [Number(t.a.player.id), Number(t.b.player.id)]);
    const ratings = await query<{ games: number }>('SELECT games FROM ratings WHERE player_id = ANY($1)', [players]);
    expect(ratings.every((r) => r.games === 1)).toBe(true);
    expect(ratings.length).toBe(2 * results.filter((r) => r.rated === 1).length);
    // The finished tables leave every lobby alike.
    await agreedLobby(watchers, (ids) => ids.length === 0);
  }, 300_000);

  it('goes on after kill -9 of the room owner: another process takes the room within 10 s, no move lost or doubled', async () => {
    url = await db.database('failover');
    await start(3);
    const [p1, p2, p3] = procs as [ServerProcess, ServerProcess, ServerProcess];
    const { a, b, room } = await table(p1, p2, 'nineball', ['Owner-side', 'Other-side'], 3);
    // Watching before the first shot: the spectator sees every one.
    const s = await seat(p3, { name: 'Watcher' });
    await ask(s, { type: 'watch', room });
    await playOut(a, b, room, async (n) => {
      if (n === 3) throw new Error('stop');
    }).catch((err: unknown) => {
      if ((err as Error).message !== 'stop') throw err;
    });
    const before = a.rooms.get(room)!;
    expect(before.status).toBe('playing');
    await until(b, room, (r) => r.stateId === before.stateId);
    await until(s, room, (r) => r.stateId === before.stateId);

    // The owner (p1, where the room was made) dies; its player comes back through p3.
    const killedAt = Date.now();
    expect(await p1.stop('SIGKILL')).toBeNull();
    const a2 = await seat(p3, { token: a.token });
    const onTurn = before.game!.turn === a.player.id ? a2 : b;
    await until(onTurn, room, (r) => r.stateId === before.stateId, 15_000);
    const first = await shoot(onTurn, room);
    const failoverMs = Date.now() - killedAt;
    expect(first.stateId).toBe(before.stateId + 1);
    console.log(`failover: first shot accepted ${failoverMs} ms after kill -9 of the owner`);
    expect(failoverMs).toBeLessThan(10_000);

    await playOut(b, a2, room);
    const final = b.rooms.get(room)!;
    expect(final.status).toBe('over');
    await until(s, room, (r) => r.status === 'over');
    // The spectator on p3 saw every shot, before and after; the stored match replays to them.
    const seen = shotsIn(b, room).map((m) => m.outcome.hash);
    expect(shotsIn(s, room).map((m) => m.outcome.hash)).toEqual(seen);
    const record = (await (await fetch(`${p2.url}/api/matches/${final.view!.match}`)).json()) as MatchRecord;
    expect(replayMatch(record).shots.map((x) => x.hash)).toEqual(seen);
    const actions = await query<{ seq: number }>('SELECT seq FROM match_actions WHERE match_id = $1 ORDER BY seq', [final.view!.match]);
    expect(actions.map((x) => x.seq)).toEqual(Array.from({ length: actions.length }, (_, i) => i + 2));
    expect(await query('SELECT 1 FROM results WHERE match_id = $1', [final.view!.match])).toHaveLength(1);
  }, 120_000);

  it('hands the rooms of a process stopped with SIGTERM to another within seconds', async () => {
    url = await db.database('rolling');
    await start(2);
    const [p1, p2] = procs as [ServerProcess, ServerProcess];
    const { a, b, room } = await table(p1, p2, 'eightball', ['Leaving-side', 'Staying-side']);
    const a2 = await seat(p2, { token: a.token });
    await until(a2, room, (r) => r.status === 'playing');
    const stoppedAt = Date.now();
    expect(await p1.stop('SIGTERM')).toBe(0);
    const onTurn = a2.rooms.get(room)!.game!.turn === a2.player.id ? a2 : b;
    const shot = await shoot(onTurn, room);
    const ms = Date.now() - stoppedAt;
    expect(shot.stateId).toBe(2);
    // The leases given up, no waiting for them to lapse (6 s).
    expect(ms).toBeLessThan(4_000);
  }, 60_000);

  it('survives a stalled owner: another takes the room, the stalled one steps down and plays on through it', async () => {
    url = await db.database('stalled');
    await start(2);
    const [p1, p2] = procs as [ServerProcess, ServerProcess];
    const { a, b, room } = await table(p1, p2, 'nineball', ['Stalled-side', 'Live-side'], 3);
    // Play until it is b's turn, so that b can shoot while p1 is frozen.
    while (a.rooms.get(room)!.game!.turn === a.player.id) {
      const shot = await shoot(a, room);
      await until(b, room, (r) => r.stateId >= shot.stateId);
    }
    const before = a.rooms.get(room)!.stateId;
    await until(b, room, (r) => r.stateId === before);

    // p1 (the owner) freezes past the lease: p2 takes the room and b plays on.
    p1.child.kill('SIGSTOP');
    let frozenShot: string;
    try {
      const first = await shoot(b, room, 20_000);
      expect(first.stateId).toBe(before + 1);
      frozenShot = first.outcome.hash;
    } finally {
      p1.child.kill('SIGCONT');
    }
    // p1 wakes: it lists its socket again and gives the room up; a plays through it, and the
    // match goes on, every move once.
    await until(a, room, (r) => r.stateId >= before + 1, 15_000);
    await playOut(a, b, room);
    expect(b.rooms.get(room)!.status).toBe('over');
    const seen = shotsIn(b, room).map((m) => m.outcome.hash);
    // The shot made while a's process was frozen reached a as the room's state when it woke (as
    // after a reconnect); every other shot as a shot.
    expect(shotsIn(a, room).map((m) => m.outcome.hash)).toEqual(seen.filter((h) => h !== frozenShot));
    expect(a.rooms.get(room)!.game).toEqual(b.rooms.get(room)!.game);
    const match = b.rooms.get(room)!.view!.match!;
    const record = (await (await fetch(`${p2.url}/api/matches/${match}`)).json()) as MatchRecord;
    expect(replayMatch(record).shots.map((x) => x.hash)).toEqual(seen);
    const actions = await query<{ seq: number }>('SELECT seq FROM match_actions WHERE match_id = $1 ORDER BY seq', [match]);
    expect(actions.map((x) => x.seq)).toEqual(Array.from({ length: actions.length }, (_, i) => i + 2));
    expect(p1.child.exitCode).toBeNull();
  }, 120_000);

  it('holds the per-player limit of open rooms across processes, whatever junk is on the bus', async () => {
    url = await db.database('limits');
    await start(3);
    // Malformed messages between processes are logged and dropped: nothing changes, nothing crashes.
    const junk: unknown[] = [
      'not json',
      { from: 'p9' },
      { from: 'p9', body: { t: 'cmd', ref: 1, conn: 1, player: { id: '1', name: 'x' }, msg: { type: 'shot', room: 'r' } } },
      { from: 'p9', body: { t: 'out', deliveries: 'everyone' } },
      { from: 'p9', body: { t: 'room', state: { id: '', stateId: 1e300 }, spectators: [], outcome: null } },
      { from: 'p9', body: { t: 'attach', conn: -1, player: { id: '', name: 'x' } } },
      { from: 'p9', body: { t: 'detach', conn: 'all' } },
      { from: 'p9', body: { t: 'rename', player: null } },
      { from: 'p9', body: { t: 'nonsense' } },
    ];
    const c = await connectRedis(redis.url, 'junk');
    for (const m of junk) for (const channel of ['baize:deliver', 'baize:proc:p1']) await c.sendCommand(['PUBLISH', channel, typeof m === 'string' ? m : JSON.stringify(m)]);
    c.destroy();
    const first = await seat(procs[0]!, { name: 'Many-rooms' });
    const tabs = [first, await seat(procs[1]!, { token: first.token }), await seat(procs[2]!, { token: first.token })];
    const replies = await Promise.all(Array.from({ length: 8 }, (_, i) => ask(tabs[i % 3]!, { type: 'create', kind: 'nineball' })));
    expect(replies.filter((m) => m.type === 'room')).toHaveLength(5);
    expect(replies.filter((m) => m.type === 'error' && m.code === 'too-many-rooms')).toHaveLength(3);
    const open = await query<{ n: number }>("SELECT count(*)::int AS n FROM rooms WHERE status IN ('waiting', 'playing')");
    expect(open[0]!.n).toBe(5);
    for (const p of procs) expect(p.child.exitCode).toBeNull();
    expect(procs[0]!.stderr()).toMatch(/dropped a malformed message from process p9/);
  }, 60_000);
});
