// What one client can make the server send to others (issue 36, findings 5, 6 and 7), against a
// real server process over real sockets: a socket that never reads, spectators coming and going,
// a lobby of hundreds of rooms, chat from many tabs.
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import type { Socket } from 'node:net';
import { LOBBY_MAX_ROOMS, type ServerMessage } from '../../shared/protocol/index.ts';
import { ask, connect, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { endedWithin, rawSocket, receivedWithin } from '../support/raw-sockets.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

let server: ServerProcess | undefined;
const seats: Seat[] = [];
afterEach(async () => {
  await Promise.all(seats.splice(0).map((s) => s.client.close(200)));
  await server?.stop('SIGKILL');
  server = undefined;
});

async function start(env: Record<string, string> = {}): Promise<string> {
  server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db'), ...env });
  return wsUrl(server.url);
}

async function seat(url: string, hello: { name?: string; token?: string } = {}): Promise<Seat> {
  const s = await connect(url, hello);
  seats.push(s);
  return s;
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));
/** A 32-character name, the longest there is, so that lists are as large as they get. */
const longName = (i: number) => `Player-${String(i).padStart(4, '0')}-${'x'.repeat(20)}`;

/** `count` players, each with `each` new public rooms; returns the rooms' ids, oldest first. */
async function openRooms(url: string, from: number, count: number, each: number): Promise<string[]> {
  const players = await Promise.all(Array.from({ length: count }, (_, i) => seat(url, { name: longName(from + i) })));
  const ids: string[][] = await Promise.all(
    players.map(async (p) => {
      const mine: string[] = [];
      for (let k = 0; k < each; k++) {
        const m = await ask(p, { type: 'create', kind: 'threecushion' });
        if (m.type !== 'room') throw new Error(JSON.stringify(m));
        mine.push(m.room.id);
      }
      return mine;
    }),
  );
  return ids.flat();
}

describe('fan-out', () => {
  it('drops a socket that never reads once the server holds more than the threshold for it; the others are served', async () => {
    const url = await start({ BAIZE_MAX_BUFFERED_KIB: '64' });
    await openRooms(url, 0, 40, 5);
    const reader = await seat(url, { name: 'Reader' });
    const sink = await rawSocket(url);
    sink.send({ type: 'hello' });
    await receivedWithin(sink, (m) => m.type === 'welcome');
    // It stops reading: everything the server sends it piles up (first in the kernel's buffers).
    (sink.ws as unknown as { _socket: Socket })._socket.pause();
    let asked = 0;
    const t0 = Date.now();
    for (; Date.now() - t0 < 25_000 && (await endedWithin(sink, 0)) === 'open'; asked++) {
      sink.send({ type: 'lobby' }); // each answer is the list of 200 rooms, some 30 KB
      if (asked >= 30) await sleep(55); // within the rate limit of 20 a second
    }
    // Cut off (no close handshake: it would not read one), after far fewer answers than asked.
    expect(await endedWithin(sink, 5000)).toMatchObject({ code: 1006 });
    expect(asked).toBeLessThan(450);
    const list = await ask(reader, { type: 'lobby' });
    expect(list.type === 'lobby' && list.rooms.length).toBe(200);
  }, 60_000);

  it('sends spectators coming and going as at most one room update per tick; moves go out at once', async () => {
    const url = await start();
    const a = await seat(url, { name: 'Ann' });
    const b = await seat(url, { name: 'Bob' });
    const created = await ask(a, { type: 'create', kind: 'nineball' });
    const room = created.type === 'room' ? created.room.id : '';
    await ask(b, { type: 'join', room });
    await until(a, room, (r) => r.status === 'playing');
    const observer = await seat(url, { name: 'Observer' });
    await ask(observer, { type: 'watch', room });
    const churners = await Promise.all(Array.from({ length: 20 }, (_, i) => seat(url, { name: `Churn-${i}` })));
    await sleep(600);
    const from = observer.log.length;
    const t0 = Date.now();
    const churn = Promise.all(
      churners.map(async (c) => {
        for (let k = 0; k < 10; k++) {
          await ask(c, { type: 'watch', room });
          await ask(c, { type: 'leave', room });
        }
      }),
    );
    const shot = await playTurn(a, room);
    await churn;
    const elapsed = Date.now() - t0;
    await sleep(600);
    const seen = observer.log.slice(from);
    const updates = seen.filter((m) => m.type === 'room' && m.room.id === room);
    // 400 changes of the spectators; the room's members hear of them once a tick (250 ms) at most.
    expect(updates.length).toBeLessThanOrEqual(Math.ceil((elapsed + 600) / 250) + 2);
    expect(seen.some((m) => m.type === 'shot' && m.stateId === shot.stateId)).toBe(true);
    const lastView = updates.at(-1) as Extract<ServerMessage, { type: 'room' }>;
    expect(lastView.room).toMatchObject({ spectators: 1, stateId: shot.stateId });
  }, 60_000);

  it('lists at most 200 rooms, waiting ones first, with the count of the rest; updates once a second at most', async () => {
    const url = await start();
    const subscriber = await seat(url, { name: 'Subscriber' });
    await ask(subscriber, { type: 'lobby' });
    const from = subscriber.log.length;
    const t0 = Date.now();
    const first = await openRooms(url, 0, 40, 5);
    // The oldest 60 become games in play.
    const joiners = await Promise.all(first.slice(0, 60).map((_, i) => seat(url, { name: `Joiner-${i}` })));
    await Promise.all(joiners.map((j, i) => ask(j, { type: 'join', room: first[i]! })));
    const later = await openRooms(url, 40, 10, 5);
    const elapsed = Date.now() - t0;
    await sleep(1500);
    const updates = subscriber.log.slice(from).filter((m) => m.type === 'lobby' && m.re === undefined);
    expect(updates.length).toBeLessThanOrEqual(Math.ceil((elapsed + 1500) / 1000) + 1);
    const list = await ask(subscriber, { type: 'lobby' });
    if (list.type !== 'lobby') throw new Error(JSON.stringify(list));
    expect(list.rooms).toHaveLength(LOBBY_MAX_ROOMS);
    expect(list.more).toBe(50);
    // Every waiting room first, then games in play.
    const waiting = [...first.slice(60), ...later].sort();
    expect(list.rooms.slice(0, 190).map((r) => r.id).sort()).toEqual(waiting);
    expect(list.rooms.slice(0, 190).every((r) => r.status === 'waiting')).toBe(true);
    expect(list.rooms.slice(190).every((r) => r.status === 'playing' && first.slice(0, 60).includes(r.id))).toBe(true);
    // The last update sent is the latest list.
    const lastUpdate = updates.at(-1) as Extract<ServerMessage, { type: 'lobby' }>;
    expect(lastUpdate.rooms).toEqual(list.rooms);
  }, 60_000);

  it('limits chat per player across all their tabs and per room, telling the sender how long to wait', async () => {
    const url = await start();
    const p = await seat(url, { name: 'Talker' });
    const created = await ask(p, { type: 'create', kind: 'snooker' });
    const room = created.type === 'room' ? created.room.id : '';
    const tabs = [p, await seat(url, { token: p.token }), await seat(url, { token: p.token })];
    const spectator = await seat(url, { name: 'Listener' });
    await ask(spectator, { type: 'watch', room });
    const others = await Promise.all([1, 2, 3, 4].map((i) => seat(url, { name: `Other-${i}` })));
    for (const o of others) await ask(o, { type: 'watch', room });
    const refusals: Extract<ServerMessage, { type: 'error' }>[] = [];
    /** Says a line; resolves once it is known whether it went out (the sender's tab gets it too) or was refused. */
    const say = async (s: Seat, text: string) => {
      const id = s.client.newId();
      const outcome = s.client.waitFor((m) => (m.type === 'error' && m.re === id) || (m.type === 'chat' && m.text === text));
      s.client.send({ type: 'chat', room, text, id });
      const m = await outcome;
      if (m.type === 'error') refusals.push(m);
    };
    const t0 = Date.now();
    await Promise.all(Array.from({ length: 8 }, (_, i) => say(tabs[i % 3]!, `mine ${i}`)));
    // Five lines a player in ten seconds, whichever tab they come from.
    expect(refusals.map((r) => r.code)).toEqual(['rate-limited', 'rate-limited', 'rate-limited']);
    expect(refusals[0]!.message).toMatch(/^you are sending messages too fast; wait ([1-9]|10) s$/);
    await Promise.all(others.flatMap((o, i) => Array.from({ length: 5 }, (_, k) => say(o, `other ${i} ${k}`))));
    const elapsed = Date.now() - t0;
    // Twenty lines a room in ten seconds (two a second come back).
    const passed = 28 - refusals.length;
    expect(passed).toBeGreaterThanOrEqual(20);
    expect(passed).toBeLessThanOrEqual(20 + Math.floor((elapsed / 1000) * 2));
    expect(refusals.at(-1)!.message).toMatch(/^this room is receiving messages too fast; wait \d+ s$/);
    await sleep(300);
    expect(spectator.log.filter((m) => m.type === 'chat')).toHaveLength(passed);
  }, 60_000);
});
