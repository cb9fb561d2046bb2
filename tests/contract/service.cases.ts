// The game service's cases (sessions, rooms, turns, the shot clock, held seats and claims,
// rematches, limits), run against a service over a SQLite file (tests/unit/server/service.test.ts)
// and over PostgreSQL (tests/integration/service-postgres.test.ts): call serviceCases with a
// function that opens a harness on a fresh database.
import { afterEach, describe, expect, it } from 'vitest';
import { simulate } from '../../shared/physics/index.ts';
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { sceneOf, strikeOf } from '../../shared/rules/index.ts';
import { last, type Harness, type HarnessOptions } from '../support/service-harness.ts';

export function serviceCases(open: (options?: HarnessOptions) => Promise<Harness>): void {
  let h: Harness;
  afterEach(async () => h?.close());

  async function welcome(h: Harness, conn: number, name?: string, token?: string) {
    await h.send(conn, { type: 'hello', ...(name ? { name } : {}), ...(token ? { token } : {}) });
    return last(h, conn, 'welcome');
  }

  /** Two players at a nine-ball table (connections 1 and 2); returns the room. */
  async function table(h: Harness, kind: 'nineball' | 'eightball' | 'snooker' | 'threecushion' = 'nineball', extra: { shotClock?: number; raceTo?: number } = {}): Promise<RoomView> {
    await welcome(h, 1, 'Ann');
    await welcome(h, 2, 'Bob');
    await h.send(1, { type: 'create', kind, ...extra });
    const id = last(h, 1, 'room').room.id;
    await h.send(2, { type: 'join', room: id });
    return last(h, 2, 'room').room;
  }

  const errorOf = (msgs: ServerMessage[] | undefined) => msgs?.find((m) => m.type === 'error') as Extract<ServerMessage, { type: 'error' }> | undefined;

  describe('the game service', () => {
    it('welcomes guests with unique names and made-up ones, and knows them again by token', async () => {
      h = await open();
      const ann = await welcome(h, 1, 'Ann');
      expect(ann.player.name).toBe('Ann');
      expect(ann.token.length).toBeGreaterThan(30);
      expect(errorOf((await h.send(2, { type: 'hello', name: 'ANN' })).get(2))?.code).toBe('name-taken');
      const guest = await welcome(h, 3);
      expect(guest.player.name).toMatch(/^Guest-[A-Z2-9]{8}$/);
      const again = await welcome(h, 4, undefined, ann.token);
      expect(again.player).toEqual(ann.player);
      expect(errorOf((await h.send(5, { type: 'hello', token: 'forged' })).get(5))?.code).toBe('bad-token');
      expect(errorOf((await h.send(6, { type: 'lobby' })).get(6))?.code).toBe('not-welcomed');
    });

    it('lists public rooms in the lobby, keeps private ones out, and updates subscribers at the next tick', async () => {
      h = await open();
      await welcome(h, 1, 'Ann');
      await welcome(h, 2, 'Bob');
      await h.send(2, { type: 'lobby' });
      expect(last(h, 2, 'lobby')).toMatchObject({ rooms: [], more: 0 });
      await h.send(1, { type: 'create', kind: 'snooker', raceTo: 3 });
      await h.send(1, { type: 'create', kind: 'nineball', private: true });
      h.clock += 1000;
      await h.tick();
      const rooms = last(h, 2, 'lobby').rooms;
      expect(rooms).toHaveLength(1);
      expect(rooms[0]).toMatchObject({ kind: 'snooker', raceTo: 3, players: [{ name: 'Ann' }], spectators: 0, status: 'waiting' });
      // watch: false stops the updates; a later lobby request starts them again.
      await h.send(2, { type: 'lobby', watch: false });
      await h.send(1, { type: 'create', kind: 'eightball' });
      h.clock += 1000;
      expect((await h.tick()).get(2)?.some((m) => m.type === 'lobby')).toBeFalsy();
      await h.send(2, { type: 'lobby' });
      expect(last(h, 2, 'lobby').rooms).toHaveLength(2);
      await h.send(1, { type: 'create', kind: 'threecushion' });
      h.clock += 1000;
      expect((await h.tick()).get(2)?.some((m) => m.type === 'lobby')).toBe(true);
    });

    it('starts the game on join, the creator breaking, and refuses a third player', async () => {
      h = await open();
      const room = await table(h);
      expect(room).toMatchObject({ status: 'playing', stateId: 1, players: [{ name: 'Ann', connected: true }, { name: 'Bob', connected: true }] });
      expect(room.game!.turn).toBe(room.players[0]!.id);
      await welcome(h, 3, 'Cid');
      expect(errorOf((await h.send(3, { type: 'join', room: room.id })).get(3))?.code).toBe('room-full');
      expect(errorOf((await h.send(3, { type: 'join', room: 'nowhere' })).get(3))?.code).toBe('no-room');
    });

    it('applies a room\'s commands in arrival order, each answered with its own deliveries', async () => {
      h = await open();
      const room = await table(h);
      const shot = { ball: 'cue', heading: 0, speed: 6, side: 0, top: 0 };
      // Sent at once, as a double click and a chat would be: the second shot is checked against the
      // state the first committed, and nobody's answer holds another's messages.
      const [first, again, chat] = await Promise.all([
        h.service.handle(1, { type: 'shot', id: 'a', room: room.id, stateId: 1, shot }),
        h.service.handle(1, { type: 'shot', id: 'b', room: room.id, stateId: 1, shot }),
        h.service.handle(2, { type: 'chat', id: 'c', room: room.id, text: 'nice' }),
      ]);
      const types = (d: typeof first) => d.map((x) => x.message.type);
      expect(first.find((d) => d.to.includes(1))?.message).toMatchObject({ type: 'shot', re: 'a', stateId: 2 });
      expect(again).toEqual([{ to: [1], message: expect.objectContaining({ type: 'error', re: 'b', code: 'stale-state', message: 'the room is at stateId 2, not 1' }) }]);
      expect(types(chat)).toEqual(['chat']);
      expect(types(first)).not.toContain('chat');
      expect((await h.store.matchActions(room.match!)).map((a) => a.seq)).toEqual([2]);
    });

    it('plays a shot: everyone gets the outcome of simulate(sceneOf(game)) and the next game; stale and out-of-turn moves change nothing', async () => {
      h = await open();
      const room = await table(h);
      await h.send(3, { type: 'hello', name: 'Eve' });
      await h.send(3, { type: 'watch', room: room.id });
      const shot = { ball: 'cue', heading: 0, speed: 7, side: 0, top: 0.1 };
      expect(errorOf((await h.send(2, { type: 'shot', room: room.id, stateId: 1, shot })).get(2))?.code).toBe('not-your-turn');
      expect(errorOf((await h.send(1, { type: 'shot', room: room.id, stateId: 0, shot })).get(1))?.code).toBe('stale-state');
      const got = await h.send(1, { type: 'shot', room: room.id, stateId: 1, shot });
      const expected = simulate(sceneOf(room.game!), strikeOf({ ...shot, player: room.players[0]!.id }));
      for (const conn of [1, 2, 3]) {
        const m = got.get(conn)!.find((x) => x.type === 'shot') as Extract<ServerMessage, { type: 'shot' }>;
        expect(m.stateId).toBe(2);
        expect(m.outcome.hash).toBe(expected.hash);
        expect(m.game.shots).toBe(1);
      }
      expect(errorOf((await h.send(1, { type: 'shot', room: room.id, stateId: 1, shot })).get(1))?.code).toBe('stale-state');
    });

    it('refuses a shot the physics or the rules refuse, and changes nothing', async () => {
      h = await open();
      const room = await table(h);
      const base = { type: 'shot', room: room.id, stateId: 1 } as const;
      expect(errorOf((await h.send(1, { ...base, shot: { ball: 'cue', heading: 0, speed: 3, side: 0.45, top: 0.45 } })).get(1))?.code).toBe('miscue');
      expect(errorOf((await h.send(1, { ...base, shot: { ball: '9', heading: 0, speed: 3, side: 0, top: 0 } })).get(1))?.code).toBe('wrong-ball');
      expect(errorOf((await h.send(1, { ...base, shot: { ball: 'cue', heading: 0, speed: 3, side: 0, top: 0 }, cueBall: { x: 0.5, y: 0 } })).get(1))?.code).toBe('bad-placement');
      await h.send(1, { type: 'watch', room: room.id });
      expect(last(h, 1, 'room').room.stateId).toBe(1);
    });

    it('runs the shot clock: the player who runs out of time is given the game\'s foul', async () => {
      h = await open();
      const room = await table(h, 'nineball', { shotClock: 30 });
      expect(room.deadline).toBe(h.clock + 30_000);
      h.clock += 29_000;
      expect((await h.tick()).size).toBe(0);
      h.clock += 1_000;
      await h.tick();
      const after = last(h, 2, 'room').room;
      expect(after.stateId).toBe(2);
      expect(after.game!.turn).toBe(room.players[1]!.id);
      expect(after.game!.verdict).toMatchObject({ foul: true, message: expect.stringContaining('ran out of time') });
      expect(after.deadline).toBe(h.clock + 30_000);
    });

    it('starts the next player\'s clock once the balls of a shot have stopped', async () => {
      h = await open();
      const room = await table(h, 'nineball', { shotClock: 30 });
      const shot = { ball: 'cue', heading: 0, speed: 7, side: 0, top: 0.1 };
      const got = await h.send(1, { type: 'shot', room: room.id, stateId: 1, shot });
      const m = got.get(2)!.find((x) => x.type === 'shot') as Extract<ServerMessage, { type: 'shot' }>;
      expect(m.outcome.duration).toBeGreaterThan(1);
      expect(m.deadline).toBe(h.clock + Math.ceil(m.outcome.duration * 1000) + 30_000);
      // While the balls still roll, and for 30 s after, nobody runs out of time.
      h.clock = m.deadline! - 1;
      expect((await h.tick()).size).toBe(0);
      h.clock += 1;
      await h.tick();
      expect(last(h, 1, 'room').room.game!.verdict).toMatchObject({ message: expect.stringContaining('ran out of time') });
    });

    it('stops the clock while nobody is there, and starts it again for the player on turn who comes back', async () => {
      h = await open({ seatHoldMs: 60_000 });
      const room = await table(h, 'nineball', { shotClock: 30 });
      const annToken = last(h, 1, 'welcome').token;
      await h.send(3, { type: 'hello', name: 'Eve' });
      await h.send(3, { type: 'watch', room: room.id });
      await h.drop(1);
      await h.drop(2);
      for (let k = 0; k < 10; k++) {
        h.clock += 30_000;
        await h.tick();
      }
      // No foul was played for the absent players, and the spectator sees the clock stopped.
      const seen = last(h, 3, 'room').room;
      expect(seen).toMatchObject({ status: 'playing', stateId: 1 });
      expect(seen.deadline).toBeUndefined();
      expect(await h.store.resultCount()).toBe(0);
      // Nor is the paused game offered in the lobby.
      await h.send(3, { type: 'lobby' });
      expect(last(h, 3, 'lobby').rooms).toEqual([]);
      await h.send(7, { type: 'hello', token: annToken });
      await h.send(3, { type: 'lobby' });
      expect(last(h, 3, 'lobby').rooms.map((r) => r.id)).toEqual([room.id]);
      const back = last(h, 7, 'room').room;
      expect(back).toMatchObject({ stateId: 1, deadline: h.clock + 30_000 });
      expect(last(h, 3, 'room').room.deadline).toBe(h.clock + 30_000);
      // With a player there, the clock runs as before.
      h.clock += 30_000;
      await h.tick();
      expect(last(h, 7, 'room').room).toMatchObject({ stateId: 2, game: { verdict: { message: expect.stringContaining('ran out of time') } } });
    });

    it('closes a waiting table once its player has been gone past the seat hold, not before', async () => {
      h = await open({ seatHoldMs: 60_000 });
      await welcome(h, 1, 'Ann');
      const token = last(h, 1, 'welcome').token;
      await h.send(1, { type: 'create', kind: 'nineball' });
      const kept = last(h, 1, 'room').room.id;
      await h.send(1, { type: 'create', kind: 'snooker' });
      const gone = last(h, 1, 'room').room.id;
      await welcome(h, 2, 'Bob');
      await h.send(2, { type: 'lobby' });
      expect(last(h, 2, 'lobby').rooms.map((r) => r.id)).toEqual([kept, gone]);
      await h.drop(1);
      h.clock += 59_000;
      await h.tick();
      // Back within the hold: both tables wait on. Then gone again, past the hold: both close.
      await h.send(8, { type: 'hello', token });
      await h.drop(8);
      h.clock += 59_000;
      await h.tick();
      await h.send(2, { type: 'lobby' });
      expect(last(h, 2, 'lobby').rooms).toHaveLength(2);
      h.clock += 1_000;
      await h.tick();
      await h.send(2, { type: 'lobby' });
      expect(last(h, 2, 'lobby').rooms).toEqual([]);
      expect(errorOf((await h.send(2, { type: 'join', room: kept })).get(2))?.code).toBe('no-room');
    });

    it('holds a dropped seat, resumes it by token, and lets the opponent claim after the hold', async () => {
      h = await open({ seatHoldMs: 60_000 });
      const room = await table(h);
      const annToken = last(h, 1, 'welcome').token;
      await h.drop(1);
      const seen = last(h, 2, 'room').room.players[0]!;
      expect(seen).toMatchObject({ connected: false, heldUntil: h.clock + 60_000 });
      expect(errorOf((await h.send(2, { type: 'claim', room: room.id })).get(2))?.code).toBe('not-claimable');
      // Back within the hold: the same seat, the current state.
      await h.send(7, { type: 'hello', token: annToken });
      expect(last(h, 7, 'room').room).toMatchObject({ id: room.id, stateId: 1, players: [{ connected: true }, { connected: true }] });
      await h.drop(7);
      h.clock += 60_000;
      await h.tick();
      await h.send(2, { type: 'claim', room: room.id });
      expect(last(h, 2, 'room').room).toMatchObject({ status: 'over', winner: room.players[1]!.id });
      expect(await h.store.resultCount()).toBe(1);
    });

    it('says once a match is over whether it counts for the ratings, and why not: a real game of 3 shots each and a minute', async () => {
      h = await open();
      // Eight-ball: a stroke into nothing is a foul but, unlike nine-ball's third, never loses the rack.
      let room = await table(h, 'eightball');
      await h.send(1, { type: 'concede', room: room.id });
      expect(last(h, 2, 'room').room).toMatchObject({ status: 'over', rated: false, unrated: 'each player must take at least 3 shots' });
      const soft = { ball: 'cue', heading: Math.PI, speed: 0.05, side: 0, top: 0 };
      /** A new table where the players stroke the cue ball into nothing `shots` times in turn, `wait` ms after the start; then Bob concedes. */
      const play = async (shots: number, wait: number) => {
        await h.close();
        h = await open();
        room = await table(h, 'eightball');
        let state = { stateId: room.stateId, turn: room.game!.turn };
        for (let k = 0; k < shots; k++) {
          const conn = state.turn === room.players[0]!.id ? 1 : 2;
          const got = (await h.send(conn, { type: 'shot', room: room.id, stateId: state.stateId, shot: soft })).get(conn)!;
          const m = got.find((x) => x.type === 'shot') as Extract<ServerMessage, { type: 'shot' }>;
          state = { stateId: m.stateId, turn: m.game.turn };
        }
        h.clock += wait;
        expect(last(h, 1, 'room').room.rated).toBeUndefined(); // not over yet
        await h.send(2, { type: 'concede', room: room.id });
        return last(h, 1, 'room').room;
      };
      expect(await play(5, 60_000)).toMatchObject({ status: 'over', rated: false, unrated: 'each player must take at least 3 shots' });
      expect(await play(6, 59_999)).toMatchObject({ status: 'over', rated: false, unrated: 'a rated match lasts at least 60 s' });
      const rated = await play(6, 60_000);
      expect(rated).toMatchObject({ status: 'over', rated: true });
      expect(rated.unrated).toBeUndefined();
    });

    it('gives a rematch in the same room when both ask, the other player breaking', async () => {
      h = await open();
      const room = await table(h);
      await h.send(1, { type: 'concede', room: room.id });
      expect(last(h, 1, 'room').room).toMatchObject({ status: 'over', winner: room.players[1]!.id, rematch: [] });
      await h.send(1, { type: 'rematch', room: room.id });
      expect(last(h, 2, 'room').room.rematch).toEqual([room.players[0]!.id]);
      await h.send(2, { type: 'rematch', room: room.id });
      const again = last(h, 1, 'room').room;
      expect(again).toMatchObject({ status: 'playing', stateId: 3 });
      expect(again.game!.turn).toBe(room.players[1]!.id);
      expect(await h.store.resultCount()).toBe(1);
    });

    it('limits each player to five open rooms and chat to the room\'s members', async () => {
      h = await open();
      await welcome(h, 1, 'Ann');
      for (let i = 0; i < 5; i++) await h.send(1, { type: 'create', kind: 'threecushion' });
      expect(errorOf((await h.send(1, { type: 'create', kind: 'threecushion' })).get(1))?.code).toBe('too-many-rooms');
      const room = last(h, 1, 'room').room;
      await welcome(h, 2, 'Bob');
      expect(errorOf((await h.send(2, { type: 'chat', room: room.id, text: 'hi' })).get(2))?.code).toBe('not-seated');
      await h.send(2, { type: 'watch', room: room.id });
      const got = await h.send(2, { type: 'chat', room: room.id, text: '<img src=x onerror=alert(1)>' });
      expect(got.get(1)?.[0]).toMatchObject({ type: 'chat', from: { name: 'Bob' }, text: '<img src=x onerror=alert(1)>' });
    });
  });

  describe('leaving and closing rooms', () => {
    it('closes a finished room once both players have left, or by itself after a while', async () => {
      h = await open();
      const room = await table(h);
      await h.send(1, { type: 'leave', room: room.id });
      expect(last(h, 1, 'left').room).toBe(room.id);
      const seen = last(h, 2, 'room').room;
      expect(seen).toMatchObject({ status: 'over', winner: room.players[1]!.id });
      expect(h.inbox(2).filter((m) => m.type === 'room' && m.room.status === 'over')).toHaveLength(1);
      expect(errorOf((await h.send(2, { type: 'rematch', room: room.id })).get(2))?.code).toBe('not-playing');
      await h.send(2, { type: 'leave', room: room.id });
      expect(errorOf((await h.send(2, { type: 'watch', room: room.id })).get(2))?.code).toBe('no-room');
      // A finished room nobody leaves closes after OVER_KEEP_MS.
      await h.send(1, { type: 'create', kind: 'eightball' });
      const second = last(h, 1, 'room').room.id;
      await h.send(2, { type: 'join', room: second });
      await h.send(2, { type: 'concede', room: second });
      h.clock += 10 * 60 * 1000;
      await h.tick();
      expect(errorOf((await h.send(1, { type: 'watch', room: second })).get(1))?.code).toBe('no-room');
      expect(await h.store.resultCount()).toBe(2);
    });
  });

  describe('many tabs of one player', () => {
    it('sends every tab the room\'s messages; the seat stays connected while any tab is open', async () => {
      h = await open();
      const room = await table(h);
      const token = last(h, 2, 'welcome').token;
      await h.send(12, { type: 'hello', token });
      expect(last(h, 12, 'room').room.id).toBe(room.id);
      const got = await h.send(1, { type: 'shot', room: room.id, stateId: 1, shot: { ball: 'cue', heading: 0, speed: 6, side: 0, top: 0 } });
      expect(got.get(2)?.[0]?.type).toBe('shot');
      expect(got.get(12)?.[0]).toEqual(got.get(2)?.[0]);
      // Closing one tab changes nothing for the room: no message, the seat still connected.
      expect((await h.drop(2)).size).toBe(0);
      await h.send(3, { type: 'hello', name: 'Eve' });
      await h.send(3, { type: 'watch', room: room.id });
      expect(last(h, 3, 'room').room.players[1]).toMatchObject({ connected: true });
      expect(last(h, 3, 'room').room.players[1]!.heldUntil).toBeUndefined();
    });
  });

  describe('spectators', () => {
    it('stops counting a spectator who takes the free seat', async () => {
      h = await open();
      await welcome(h, 1, 'Ann');
      await welcome(h, 2, 'Bob');
      await h.send(1, { type: 'create', kind: 'nineball' });
      const id = last(h, 1, 'room').room.id;
      await h.send(2, { type: 'watch', room: id });
      await h.tick(); // spectators come and go in the room's next update
      expect(last(h, 1, 'room').room.spectators).toBe(1);
      await h.send(2, { type: 'join', room: id });
      expect(last(h, 1, 'room').room).toMatchObject({ status: 'playing', spectators: 0 });
    });
  });
}
