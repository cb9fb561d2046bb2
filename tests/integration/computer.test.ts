// Playing the computer over real sockets against a real server: a whole game of each kind, the
// computer's moves arriving as the same messages as a person's, the match recorded, replayable and
// never rated; rematch; leaving; bad levels refused.
import { join } from 'node:path';
import * as v from 'valibot';
import { afterEach, describe, expect, it } from 'vitest';
import { ShotSchema, type ServerMessage } from '../../shared/protocol/index.ts';
import { replayMatch, type MatchRecord } from '../../shared/rules/index.ts';
import { ask, connect, playTurn, until, wsUrl, type Seat } from '../support/game-clients.ts';
import { startServerProcess, tempDir, type ServerProcess } from '../support/server-process.ts';

type Kind = 'nineball' | 'eightball' | 'snooker' | 'threecushion';
type ShotMsg = Extract<ServerMessage, { type: 'shot' }>;

let server: ServerProcess | undefined;
const seats: Seat[] = [];
afterEach(async () => {
  await Promise.all(seats.splice(0).map((s) => s.client.close(200)));
  await server?.stop('SIGKILL');
  server = undefined;
});

async function start(env: Record<string, string> = {}) {
  server = await startServerProcess({ BAIZE_DB: join(tempDir(), 'baize.db'), BAIZE_COMPUTER_PAUSE_MS: '50', ...env });
  return wsUrl(server.url);
}

async function seat(url: string, name: string): Promise<Seat> {
  const s = await connect(url, { name });
  seats.push(s);
  return s;
}

async function get(path: string): Promise<any> {
  return (await fetch(`${server!.url}${path}`)).json();
}

/** Opens a table against the computer: the reply is the room, already playing, the person breaking. */
async function versus(me: Seat, kind: Kind, level: number, raceTo?: number): Promise<string> {
  const reply = await ask(me, { type: 'create', kind, computer: level, ...(raceTo ? { raceTo } : {}) });
  if (reply.type !== 'room') throw new Error(JSON.stringify(reply));
  expect(reply.room.status).toBe('playing');
  expect(reply.room.players.map((p) => p.name)).toEqual([me.player.name, `Computer (level ${level})`]);
  expect(reply.room.players[1]!.connected).toBe(true);
  expect(reply.room.game!.turn).toBe(me.player.id);
  return reply.room.id;
}

/**
 * Plays the person's turns with the bots' sound strategy and waits out the computer's, until the
 * match is over or, when `concedeAfter` is given, the computer has moved that often (then concedes).
 */
async function playOut(me: Seat, room: string, concedeAfter = Infinity): Promise<number> {
  let computerMoves = 0;
  for (let step = 0; step < 1000; step++) {
    const r = me.rooms.get(room)!;
    if (r.status !== 'playing') return computerMoves;
    if (r.game!.turn === me.player.id) {
      await playTurn(me, room);
    } else {
      if (computerMoves >= concedeAfter) {
        expect((await ask(me, { type: 'concede', room })).type).toBe('room');
        await until(me, room, (x) => x.status === 'over');
        return computerMoves;
      }
      await until(me, room, (x) => x.stateId > r.stateId || x.status !== 'playing', 60_000);
      computerMoves++;
    }
    // A shot that ends a frame or the match is followed by the room's new state.
    await until(me, room, (x) => x.status !== 'playing' || x.game?.winner === null);
  }
  throw new Error('the game did not end in 1000 moves');
}

const shotsOf = (log: readonly ServerMessage[], match: number) => log.filter((m): m is ShotMsg => m.type === 'shot' && m.match === match);

/** A game of `kind` against the computer, played out, and what it left: messages, record, ratings. */
async function oneGame(url: string, kind: Kind, level: number, raceTo: number, concedeAfter: number): Promise<void> {
  const me = await seat(url, `Person-${kind}`);
  const room = await versus(me, kind, level, raceTo);
  const computer = me.rooms.get(room)!.view!.players[1]!.id;
  let moves = await playOut(me, room, concedeAfter);
  if (moves === 0) {
    // The person won before the computer's first turn (a run-out from the break): a rematch,
    // which the computer breaks.
    const first = me.rooms.get(room)!.view!.match!;
    expect((await ask(me, { type: 'rematch', room })).type).toBe('room');
    await until(me, room, (x) => x.status === 'playing' && x.view!.match !== first);
    moves = await playOut(me, room, concedeAfter);
  }
  expect(moves).toBeGreaterThan(0);
  const final = me.rooms.get(room)!;
  expect(final.status).toBe('over');
  const matchId = final.view!.match!;
  // Nine-ball and eight-ball end by the rules; the others by the rules or the person's concession.
  expect(final.view!.winner).toBe(final.game!.winner);
  if (concedeAfter === Infinity) expect(final.game!.verdict!.loss).not.toBe('concession');
  const shots = shotsOf(me.log, matchId);
  const mine = me.log.filter((m): m is ShotMsg => m.type === 'shot' && m.shot.player === me.player.id).map(({ re: _re, ...m }) => m);
  const its = shots.filter((m) => m.shot.player === computer);
  // The computer's strokes: the same message as a person's, a stroke that passes the schema a
  // person's shot passes, and no request id (nobody asked).
  expect(its.length).toBeGreaterThan(0);
  const form = (m: object) => Object.keys(m).filter((k) => k !== 'cueBall' && k !== 'deadline').sort();
  for (const m of its) {
    expect(form(m)).toEqual(form(mine[0]!));
    expect(m.re).toBeUndefined();
    const { player: _p, ...stroke } = m.shot;
    expect(v.safeParse(ShotSchema, stroke).success).toBe(true);
    expect(typeof m.outcome.hash).toBe('string');
  }
  // Recorded and replayable: the replay's hashes are the broadcast ones, its end the room's.
  const record = (await get(`/api/matches/${matchId}`)) as MatchRecord & { result: unknown };
  const replayed = replayMatch(record);
  expect(replayed.shots.map((x) => x.hash)).toEqual(shots.map((m) => m.outcome.hash));
  expect(replayed.game).toEqual(final.game);
  // Never rated, for either player.
  expect(record.result).toMatchObject({ rated: false, unrated: 'computer' });
  expect(final.view).toMatchObject({ rated: false, unrated: 'matches against the computer are never rated' });
  expect((await get(`/api/players/${me.player.id}`)).ratings).toEqual({});
  expect((await get(`/api/players/${computer}`)).ratings).toEqual({});
}

describe('playing the computer', () => {
  // One server, the four games at once: the computer waits for each shot's balls to stop, so the
  // games spend most of their time waiting, and side by side the test takes the longest one's.
  it('a game of each kind against the computer over real sockets: same messages, recorded, replayable, unrated', async () => {
    const url = await start({ BAIZE_RATED_MIN_PLAY_S: '0' });
    const games = [
      ['nineball', 3, 1, Infinity],
      ['eightball', 2, 1, Infinity],
      ['snooker', 1, 1, 4],
      ['threecushion', 5, 1, 4],
    ] as const;
    await Promise.all(games.map(([kind, level, raceTo, concedeAfter]) => oneGame(url, kind, level, raceTo, concedeAfter).catch((e: Error) => {
      throw new Error(`${kind} against level ${level}: ${e.message}`);
    })));
  }, 300_000);

  it('waits at least 0.8 s after the balls stop by default, plays a rematch, and ends when the person leaves', async () => {
    const url = await start({ BAIZE_COMPUTER_PAUSE_MS: '800' });
    const me = await seat(url, 'Patient');
    const room = await versus(me, 'threecushion', 1, 1);
    const computer = me.rooms.get(room)!.view!.players[1]!.id;
    // The person's strokes until the computer is on turn; then the time to its stroke.
    let mine: ShotMsg | undefined;
    let at = 0;
    while (me.rooms.get(room)!.game!.turn === me.player.id) {
      // Timed from the send: the server plays the shot no earlier, however slow the reply.
      const sent = Date.now();
      mine = await playTurn(me, room);
      at = sent;
    }
    if (me.rooms.get(room)!.status === 'playing') {
      const before = me.log.length;
      await until(me, room, (x) => x.stateId > mine!.stateId, 30_000);
      const its = me.log.slice(before).find((m): m is ShotMsg => m.type === 'shot' && m.shot.player === computer);
      expect(its).toBeDefined();
      expect(Date.now() - at).toBeGreaterThanOrEqual(mine!.outcome.duration * 1000 + 800 - 20);
    }
    // Conceding ends the match; a rematch starts at once (the computer always agrees) and it breaks.
    if (me.rooms.get(room)!.status === 'playing') await ask(me, { type: 'concede', room });
    await until(me, room, (x) => x.status === 'over');
    const first = me.rooms.get(room)!.view!.match!;
    const again = await ask(me, { type: 'rematch', room });
    expect(again.type).toBe('room');
    await until(me, room, (x) => x.status === 'playing' && x.view!.match !== first);
    expect(me.rooms.get(room)!.game!.turn).toBe(computer);
    const rematchAt = me.rooms.get(room)!.stateId;
    await until(me, room, (x) => x.stateId > rematchAt, 30_000);
    // Leaving concedes like leaving a person; the finished room then closes (the computer never stays).
    const left = await ask(me, { type: 'leave', room });
    expect(left.type).toBe('left');
    const claim = await ask(me, { type: 'watch', room });
    expect(claim.type === 'error' || (claim.type === 'room' && claim.room.status === 'over')).toBe(true);
  }, 120_000);

  it('refuses a level that is not 1 to 5 with a clear error, and names nobody after the computer', async () => {
    const url = await start();
    const me = await seat(url, 'Chooser');
    for (const bad of [0, 6, 2.5, 'x', null]) {
      const reply = await ask(me, { type: 'create', kind: 'nineball', computer: bad } as never);
      expect(reply, String(bad)).toMatchObject({ type: 'error', code: 'bad-message' });
      expect((reply as { message: string }).message).toMatch(/^computer: must be a level from 1 to 5/);
    }
    const rename = await ask(me, { type: 'rename', name: 'Computer (level 5)' });
    expect(rename).toMatchObject({ type: 'error', code: 'name-taken' });
    // The computer's seat cannot be claimed.
    const room = await versus(me, 'nineball', 1);
    expect(await ask(me, { type: 'claim', room })).toMatchObject({ type: 'error', code: 'not-claimable' });
  }, 60_000);
});
