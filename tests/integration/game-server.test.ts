// The game server as outside clients see it: a real server process on 127.0.0.1, a real SQLite
// file, real sockets. Whole games of every kind played by two bots, every broadcast checked against
// shared/physics and shared/rules; spectators; reconnection; kill -9; refusals; limits.
import { join } from 'node:path';
import Database from 'better-sqlite3';
import fc from 'fast-check';
import { afterEach, describe, expect, it } from 'vitest';
import { WebSocket } from 'ws';
import { ProtocolClient } from '../../bots/client.ts';
import { MAX_FRAME_BYTES, type ServerMessage } from '../../shared/protocol/index.ts';
import { achievements, replayMatch, type MatchRecord } from '../../shared/rules/index.ts';
import { ask, connect, playToEnd, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { hostileFrames } from '../support/hostile-messages.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

let server: ServerProcess | undefined;
const seats: Seat[] = [];
afterEach(async () => {
  await Promise.all(seats.splice(0).map((s) => s.client.close(200)));
  await server?.stop('SIGKILL');
  server = undefined;
});

async function start(env: Record<string, string> = {}, dbPath = join(tempDir(), 'baize.db')) {
  server = await startServerProcess({ BAIZE_DB: dbPath, ...env });
  return { url: wsUrl(server.url), dbPath };
}

async function seat(url: string, hello: { name?: string; token?: string }): Promise<Seat> {
  const s = await connect(url, hello);
  seats.push(s);
  return s;
}

/** Two players at a new table; the first breaks. */
async function table(url: string, kind: 'nineball' | 'eightball' | 'snooker' | 'threecushion', raceTo?: number) {
  const a = await seat(url, { name: `A-${kind}` });
  const b = await seat(url, { name: `B-${kind}` });
  const created = await ask(a, { type: 'create', kind, ...(raceTo ? { raceTo } : {}) });
  if (created.type !== 'room') throw new Error(JSON.stringify(created));
  const room = created.room.id;
  await ask(b, { type: 'join', room });
  await until(a, room, (r) => r.status === 'playing');
  return { a, b, room };
}

/** The client's socket, to send frames that are not messages. */
const raw = (cl: ProtocolClient): WebSocket => (cl as unknown as { socket: WebSocket }).socket;

const shotsOf = (log: readonly ServerMessage[], from: number) =>
  log.filter((m): m is Extract<ServerMessage, { type: 'shot' }> => m.type === 'shot' && m.stateId >= from).map(({ re: _re, ...m }) => m);

describe('the game server over real sockets', () => {
  it.each([
    ['nineball', 1],
    ['eightball', 1],
    ['snooker', 2],
    ['threecushion', 2],
  ] as const)('plays a whole game of %s (race to %i) between two bots; a late spectator sees the same stream', async (kind, raceTo) => {
    const { url } = await start();
    const { a, b, room } = await table(url, kind, raceTo);
    let spectator: Seat | undefined;
    let watchedFrom = 0;
    const shots = await playToEnd(a, b, room, 2000, async (n) => {
      if (n !== 3) return;
      spectator = await seat(url, { name: `Watcher-${kind}` });
      const now = await ask(spectator, { type: 'watch', room });
      if (now.type !== 'room') throw new Error(JSON.stringify(now));
      // The current state at once.
      expect(now.room.stateId).toBe(a.rooms.get(room)!.stateId);
      expect(now.room.game).toEqual(a.rooms.get(room)!.game);
      watchedFrom = now.room.stateId + 1;
    });
    const final = a.rooms.get(room)!;
    expect(final.status).toBe('over');
    expect(final.view!.winner).toBeTruthy();
    expect(final.view!.winner).toBe(final.game!.winner);
    // Snooker's race of frames: the winner has raceTo frames, the break alternated between them.
    if (kind === 'snooker') expect(final.view!.frames![final.view!.winner!]).toBe(raceTo);
    expect(shots).toBeGreaterThan(3);
    await until(spectator!, room, (r) => r.status === 'over');
    expect(shotsOf(spectator!.log, watchedFrom)).toEqual(shotsOf(a.log, watchedFrom));
    expect(shotsOf(b.log, 0)).toEqual(shotsOf(a.log, 0));
    // The match's record replays, with the shared rules and physics, to what the server broadcast.
    const matchId = final.view!.match!;
    const res = await fetch(`${server!.url}/api/matches/${matchId}`);
    const record = (await res.json()) as MatchRecord;
    const replayed = replayMatch(record);
    expect(replayed.shots.map((x) => x.hash)).toEqual(shotsOf(a.log, 0).map((m) => m.outcome.hash));
    expect(replayed.game).toEqual(final.game);
    // The records the match set are those its replay shows, and nothing else.
    if (kind !== 'eightball') {
      const listed = (await (await fetch(`${server!.url}/api/records?kind=${kind}&limit=100`)).json()) as { entries: { match?: number; player: { id: string }; value: number }[] };
      const mine = listed.entries.filter((e) => e.match === matchId).map((e) => ({ player: e.player.id, value: e.value }));
      const expected = achievements(record.start, replayed.games).map((x) => ({ player: x.player, value: x.value }));
      const byPlayer = (x: { player: string }, y: { player: string }) => x.player.localeCompare(y.player);
      expect(mine.sort(byPlayer)).toEqual(expected.sort(byPlayer));
    }
  }, 240_000);

  it('keeps a dropped seat: the player comes back with the token to the current state and plays on', async () => {
    const { url } = await start();
    const { a, b, room } = await table(url, 'nineball');
    await playTurn(a, room);
    await until(b, room, (r) => r.stateId === a.rooms.get(room)!.stateId);
    await b.client.close();
    seats.splice(seats.indexOf(b), 1);
    await until(a, room, (r) => r.view?.players[1]?.connected === false);
    expect(a.rooms.get(room)!.view!.players[1]!.heldUntil).toBeGreaterThan(Date.now() + 50_000);
    const back = await seat(url, { token: b.token });
    await until(back, room, (r) => r.stateId === a.rooms.get(room)!.stateId);
    expect(back.player).toEqual(b.player);
    expect(back.rooms.get(room)!.game).toEqual(a.rooms.get(room)!.game);
    await until(a, room, (r) => r.view?.players[1]?.connected === true);
    // And play goes on from there.
    const onTurn = a.rooms.get(room)!.game!.turn === a.player.id ? a : back;
    const shot = await playTurn(onTurn, room);
    expect(shot.stateId).toBe(3);
  }, 60_000);

  it('survives kill -9 mid-game: the room comes back with the same game and stateId, and play resumes', async () => {
    const dbPath = join(tempDir(), 'baize.db');
    const { url } = await start({}, dbPath);
    const { a, b, room } = await table(url, 'eightball');
    for (let i = 0; i < 3; i++) {
      const r = a.rooms.get(room)!;
      await playTurn(r.game!.turn === a.player.id ? a : b, room);
      await until(a, room, (x) => x.stateId > r.stateId);
      await until(b, room, (x) => x.stateId > r.stateId);
    }
    const before = a.rooms.get(room)!;
    expect(await server!.stop('SIGKILL')).toBeNull();
    await Promise.all([a.client.closed, b.client.closed]);
    const { url: url2 } = await start({}, dbPath);
    const a2 = await seat(url2, { token: a.token });
    const b2 = await seat(url2, { token: b.token });
    await until(a2, room, (r) => r.stateId === before.stateId);
    expect(a2.rooms.get(room)!.game).toEqual(before.game);
    expect(a2.rooms.get(room)!.status).toBe('playing');
    const onTurn = before.game!.turn === a.player.id ? a2 : b2;
    await until(onTurn, room, (r) => r.stateId === before.stateId);
    const next = await playTurn(onTurn, room);
    expect(next.stateId).toBe(before.stateId + 1);
    // A finished result is on disk once, and survives another kill -9.
    const ended = await ask(a2, { type: 'concede', room });
    expect(ended.type === 'room' && ended.room.status).toBe('over');
    expect((await ask(b2, { type: 'concede', room })).type).toBe('error');
    expect(await server!.stop('SIGKILL')).toBeNull();
    const db = new Database(dbPath, { readonly: true });
    try {
      expect(db.prepare('SELECT winner, loser, how FROM results').all()).toEqual([{ winner: Number(b.player.id), loser: Number(a.player.id), how: 'concession' }]);
      const actions = db.prepare('SELECT seq FROM match_actions ORDER BY seq').all() as { seq: number }[];
      expect(actions.map((x) => x.seq)).toEqual([2, 3, 4, 5, 6]);
    } finally {
      db.close();
    }
  }, 60_000);

  it('refuses out-of-turn, stale, unknown-room and malformed commands, and changes nothing for anyone', async () => {
    const { url } = await start();
    const { a, b, room } = await table(url, 'nineball');
    const shot = { ball: 'cue', heading: 0, speed: 7, side: 0, top: 0 };
    const refused = async (s: Seat, msg: object) => {
      const reply = await ask(s, msg as never);
      return reply.type === 'error' ? reply.code : reply.type;
    };
    expect(await refused(b, { type: 'shot', room, stateId: 1, shot })).toBe('not-your-turn');
    expect(await refused(a, { type: 'shot', room, stateId: 0, shot })).toBe('stale-state');
    expect(await refused(a, { type: 'shot', room: 'nowhere', stateId: 1, shot })).toBe('no-room');
    expect(await refused(a, { type: 'shot', room, stateId: 1, shot: { ...shot, speed: 'fast' } })).toBe('bad-message');
    expect(await refused(a, { type: 'shot', room, stateId: 1, shot: { ...shot, side: 0.45, top: 0.45 } })).toBe('miscue');
    raw(a.client).send('{"type":"shot",');
    const bad = await a.client.waitFor((m) => m.type === 'error' && m.code === 'bad-json');
    expect(bad.type).toBe('error');
    const bare = new WebSocket(url);
    await new Promise((r) => bare.once('open', r));
    const notWelcomed = await new Promise<string>((res) => {
      bare.once('message', (d) => res(String(d)));
      bare.send(JSON.stringify({ type: 'create', kind: 'nineball' }));
    });
    expect(JSON.parse(notWelcomed)).toMatchObject({ type: 'error', code: 'not-welcomed' });
    bare.close();
    // Nobody saw a change: no shot went out, and the state is where it was.
    expect(a.log.concat(b.log).some((m) => m.type === 'shot')).toBe(false);
    expect(a.rooms.get(room)!.stateId).toBe(1);
    const next = await playTurn(a, room);
    expect(next.stateId).toBe(2);
  }, 60_000);

  it('closes a socket that sends a frame over 8 KiB (1009), or floods (1008), or stops answering pings', async () => {
    const { url } = await start({ BAIZE_PING_S: '0.3' });
    const closeCode = (ws: WebSocket) => new Promise<number>((res) => ws.once('close', (code) => res(code)));
    const opened = async () => {
      const ws = new WebSocket(url);
      await new Promise((r) => ws.once('open', r));
      return ws;
    };
    const big = await opened();
    big.send(JSON.stringify({ type: 'chat', room: 'x', text: 'y'.repeat(9000) }));
    expect(await closeCode(big)).toBe(1009);
    // The bots' client keeps under the limit by itself; a raw socket does not.
    const flood = await opened();
    for (let i = 0; i < 60; i++) flood.send(JSON.stringify({ type: 'lobby' }));
    expect(await closeCode(flood)).toBe(1008);
    const mute = new WebSocket(url, { autoPong: false });
    const alive = await seat(url, { name: 'Alive' });
    const closed = await new Promise<number>((res) => mute.once('close', (code) => res(code)));
    expect(closed).toBe(1006);
    // A socket that answers pings is still there, and the server still serves.
    expect(alive.client.open).toBe(true);
    expect((await ask(alive, { type: 'lobby' })).type).toBe('lobby');
  }, 30_000);

  it('answers 2,000 hostile frames from 20 sockets within the rate limit with errors, and nothing changes', async () => {
    // The strangers never say hello, and the frames take longer than the hello deadline.
    const { url } = await start({ BAIZE_HELLO_TIMEOUT_S: '120' });
    const { a, b, room } = await table(url, 'nineball');
    const c = await seat(url, { name: 'Outsider' });
    const d = await seat(url, { name: 'Waiter' });
    const created = await ask(d, { type: 'create', kind: 'snooker' });
    const waiting = created.type === 'room' ? created.room.id : '';
    // Many sockets: more tabs of each player, and sockets that never say hello.
    const tabs = async (token: string) => Promise.all([1, 2, 3, 4].map(() => seat(url, { token })));
    const bySender = {
      onTurn: [a, ...(await tabs(a.token))].map((s) => s.client),
      waiter: [b, ...(await tabs(b.token))].map((s) => s.client),
      outsider: [c, ...(await tabs(c.token))].map((s) => s.client),
      stranger: await Promise.all([1, 2, 3, 4, 5].map(() => ProtocolClient.connect(url))),
    };
    // Frames over 8 KiB close the socket by design (tested above): these stay under it.
    const frames = fc
      .sample(hostileFrames({ playing: room, playingStateId: 1, waiting }), { numRuns: 2100, seed: 7 })
      .filter((f) => Buffer.byteLength(f.text) <= MAX_FRAME_BYTES)
      .slice(0, 2000);
    expect(frames).toHaveLength(2000);
    const sent = new Map<ProtocolClient, number>();
    const errors = new Map<ProtocolClient, number>();
    const others: ServerMessage[] = [];
    for (const list of Object.values(bySender)) {
      for (const cl of list) cl.onMessage((m) => (m.type === 'error' ? errors.set(cl, (errors.get(cl) ?? 0) + 1) : others.push(m)));
    }
    // Round robin over the 20 sockets, 200 frames a second: at most about 13 per socket, under the limit of 20.
    for (let i = 0; i < frames.length; i += 200) {
      frames.slice(i, i + 200).forEach((f, j) => {
        const list = bySender[f.sender];
        const cl = list[(i + j) % list.length]!;
        const text = f.sender === 'stranger' && f.text.includes('hello') ? '{"type":"lobby"}' : f.text;
        raw(cl).send(text);
        sent.set(cl, (sent.get(cl) ?? 0) + 1);
      });
      await new Promise((r) => setTimeout(r, 1000));
    }
    const total = () => [...errors.values()].reduce((x, y) => x + y, 0);
    for (let t = 0; t < 100 && total() < frames.length; t++) await new Promise((r) => setTimeout(r, 50));
    expect(total()).toBe(frames.length);
    for (const [cl, n] of sent) expect(errors.get(cl)).toBe(n);
    expect(others).toEqual([]);
    for (const list of Object.values(bySender)) for (const cl of list) expect(cl.open).toBe(true);
    expect(a.rooms.get(room)!.stateId).toBe(1);
    const next = await playTurn(a, room);
    expect(next.stateId).toBe(2);
    await Promise.all(bySender.stranger.map((cl) => cl.close(200)));
  }, 60_000);
});
