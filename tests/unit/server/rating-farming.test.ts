// Issue 36, finding 2: ratings farmed through the game service (a real SQLite file, the test's
// clock). A new player beating hundreds of fresh guests, and a colluding pair, played as quick
// minimal games and as minimal-but-real ones, put nobody on the leaderboard; honest play between
// different opponents still ranks players, newcomers included.
import { afterEach, describe, expect, it } from 'vitest';
import { PROVISIONAL_RD } from '../../../server/ratings/glicko2.ts';
import type { PlayerRef, RoomView, ServerMessage } from '../../../shared/protocol/index.ts';
import { generator } from '../../../shared/scenes/index.ts';
import { last, openHarness, type Harness } from '../../support/service-harness.ts';

let h: Harness;
afterEach(async () => h?.close());

const MINUTE = 60_000;
const DAY = 86_400_000;
const soft = { ball: 'cue', heading: Math.PI, speed: 0.05, side: 0, top: 0 };

interface Seat {
  readonly conn: number;
  readonly player: PlayerRef;
}

let nextConn = 1;
/** A new guest on a socket of its own, from an address of its own (no limit per address applies). */
async function guest(name: string): Promise<Seat> {
  const conn = nextConn++;
  h.open(conn, `10.${(conn >> 16) & 255}.${(conn >> 8) & 255}.${conn & 255}`);
  await h.send(conn, { type: 'hello', name });
  return { conn, player: last(h, conn, 'welcome').player };
}

/**
 * One eight-ball match as a farm plays it: `loser` opens a table, `winner` joins, each strokes the
 * cue ball into nothing (a foul that passes the turn) `shots` times, the clock moves `playMs`,
 * and `loser` concedes; both then leave. Returns the finished room as the winner saw it.
 */
async function game(winner: Seat, loser: Seat, shots: number, playMs: number): Promise<RoomView> {
  await h.send(loser.conn, { type: 'create', kind: 'eightball' });
  const id = last(h, loser.conn, 'room').room.id;
  await h.send(winner.conn, { type: 'join', room: id });
  let room = last(h, winner.conn, 'room').room;
  let state = { stateId: room.stateId, turn: room.game!.turn };
  for (let k = 0; k < 2 * shots; k++) {
    const seat = state.turn === winner.player.id ? winner : loser;
    const got = (await h.send(seat.conn, { type: 'shot', room: id, stateId: state.stateId, shot: soft })).get(seat.conn) ?? [];
    const m = got.find((x) => x.type === 'shot') as Extract<ServerMessage, { type: 'shot' }> | undefined;
    if (!m) throw new Error(`shot refused: ${JSON.stringify(got)}`);
    state = { stateId: m.stateId, turn: m.game.turn };
  }
  h.clock += playMs;
  await h.send(loser.conn, { type: 'concede', room: id });
  room = last(h, winner.conn, 'room').room;
  expect(room).toMatchObject({ status: 'over', winner: winner.player.id });
  await h.send(winner.conn, { type: 'leave', room: id });
  await h.send(loser.conn, { type: 'leave', room: id });
  return room;
}

const rating = async (p: Seat) => (await h.store.ratingsOf(Number(p.player.id))).find((r) => r.kind === 'eightball');
const board = async () => await h.store.leaderboard('eightball', 100, 0);
const onBoard = async (p: Seat) => (await board()).rows.some((r) => String(r.id) === p.player.id);

/**
 * An honest board: 12 players of different skill each play each other 3 real games in a day, the
 * stronger winning more often. Returns the players, weakest first.
 */
async function honestBoard(): Promise<Seat[]> {
  const r = generator(36);
  const players: Seat[] = [];
  for (let i = 0; i < 12; i++) players.push(await guest(`Honest-${i}`));
  const skill = (i: number) => 1300 + 40 * i;
  for (let round = 0; round < 3; round++) {
    for (let i = 0; i < players.length; i++) {
      for (let j = i + 1; j < players.length; j++) {
        const iWins = r() < 1 / (1 + 10 ** ((skill(j) - skill(i)) / 400));
        await game(iWins ? players[i]! : players[j]!, iWins ? players[j]! : players[i]!, 3, 2 * MINUTE);
      }
    }
  }
  return players;
}

describe('ratings that resist farming', () => {
  it('rates none of 300 quick minimal wins over fresh guests (two shots each, or three in seconds)', async () => {
    h = await openHarness();
    const farmer = await guest('Farmer');
    const reasons = new Map<string | undefined, number>();
    for (let i = 0; i < 300; i++) {
      // Two shots each after a minute, or three each within seconds.
      const room = i % 2 === 0 ? await game(farmer, await guest(`Fresh-${i}`), 2, MINUTE) : await game(farmer, await guest(`Fresh-${i}`), 3, 5_000);
      expect(room.rated).toBe(false);
      reasons.set(room.unrated, (reasons.get(room.unrated) ?? 0) + 1);
    }
    expect(reasons).toEqual(
      new Map([
        ['each player must take at least 3 shots', 150],
        ['a rated match lasts at least 60 s', 150],
      ]),
    );
    expect(await rating(farmer)).toBeUndefined();
    expect(await board()).toEqual({ total: 0, rows: [] });
  }, 120_000);

  it('keeps a farmer of 300 real wins over fresh guests provisional, off the board', async () => {
    h = await openHarness();
    const farmer = await guest('Farmer');
    for (let i = 0; i < 300; i++) expect((await game(farmer, await guest(`Fresh-${i}`), 3, MINUTE)).rated).toBe(true);
    // Glicko-2 learns little from beating opponents it knows nothing of: the rating soars, but its
    // RD never reaches the threshold (120 at best, after about 100 wins).
    const r = (await rating(farmer))!;
    expect(r).toMatchObject({ games: 300, wins: 300 });
    expect(r.rating).toBeGreaterThan(2500);
    expect(r.rd).toBeGreaterThanOrEqual(PROVISIONAL_RD);
    expect(await board()).toEqual({ total: 0, rows: [] });
  }, 120_000);

  it('rates 3 of a colluding pair\'s real games a day: a week of 100 a day leaves both provisional', async () => {
    h = await openHarness();
    const [a, b] = [await guest('Booster'), await guest('Partner')];
    let rated = 0;
    for (let day = 0; day < 7; day++) {
      const start = h.clock;
      for (let i = 0; i < 100; i++) {
        const room = await game(a, b, 3, MINUTE);
        if (room.rated) rated++;
        else expect(room.unrated).toBe('at most 3 rated matches of a kind between the same two players in 24 hours');
      }
      h.clock = start + DAY;
    }
    expect(rated).toBe(21);
    expect(await rating(a)).toMatchObject({ games: 21, wins: 21 });
    expect((await rating(a))!.rd).toBeGreaterThanOrEqual(PROVISIONAL_RD);
    expect(await board()).toEqual({ total: 0, rows: [] });
  }, 120_000);

  it('ranks honest players, then keeps farmers off an established board and a newcomer who plays it on', async () => {
    h = await openHarness();
    const honest = await honestBoard();
    // Real games between different opponents establish everyone, the stronger higher.
    const established = await board();
    expect(established.total).toBe(12);
    const rank = (p: Seat) => established.rows.findIndex((r) => String(r.id) === p.player.id);
    expect(rank(honest[11]!)).toBeLessThan(rank(honest[0]!));
    h.clock += DAY;

    // A farmer who mixes losses in (a win rate Glicko-2 believes) against 150 fresh guests: its
    // RD stays where it started, whatever the rating.
    const farmer = await guest('Farmer');
    for (let i = 0; i < 150; i++) {
      const fresh = await guest(`Fresh-${i}`);
      if (i < 20 ? i % 2 === 0 : i % 10 !== 0) await game(farmer, fresh, 3, MINUTE);
      else await game(fresh, farmer, 3, MINUTE);
    }
    expect((await rating(farmer))!.rd).toBeGreaterThanOrEqual(PROVISIONAL_RD);
    expect(await onBoard(farmer)).toBe(false);
    // An established player who farms fresh guests gains nothing.
    const top = honest[11]!;
    const before = (await rating(top))!.rating;
    for (let i = 0; i < 30; i++) await game(top, await guest(`Fodder-${i}`), 3, MINUTE);
    expect((await rating(top))!.rating).toBe(before);
    // Two new accounts trading wins, 3 rated games a day for 10 days, stay provisional.
    const [x, y] = [await guest('Pair-X'), await guest('Pair-Y')];
    for (let day = 0; day < 10; day++) {
      for (let i = 0; i < 3; i++) await game(i % 2 === 0 ? x : y, i % 2 === 0 ? y : x, 3, MINUTE);
      h.clock += DAY;
    }
    expect(await rating(x)).toMatchObject({ games: 30 });
    expect((await onBoard(x)) || (await onBoard(y))).toBe(false);

    // A newcomer who plays the board's players (one game each, winning half) joins it.
    const newcomer = await guest('Newcomer');
    for (let round = 0; round < 2; round++) {
      for (const [i, p] of honest.entries()) await (i % 2 === round ? game(newcomer, p, 3, MINUTE) : game(p, newcomer, 3, MINUTE));
    }
    expect((await rating(newcomer))!.rd).toBeLessThan(PROVISIONAL_RD);
    expect(await onBoard(newcomer)).toBe(true);
    expect((await board()).total).toBe(13);
  }, 240_000);
});
