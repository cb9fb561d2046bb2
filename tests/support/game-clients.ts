// Players over real sockets against a real server: welcome, the room's latest state as it streams
// in, and a bot's turn played and checked against shared/physics and shared/rules locally.
import { expect } from 'vitest';
import { ProtocolClient } from '../../bots/client.ts';
import { chooseShot } from '../../bots/strategy.ts';
import { simulate } from '../../shared/physics/index.ts';
import type { ClientMessage, PlayerRef, RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { applyShot, placeCueBall, sceneOf, strikeOf, type Game } from '../../shared/rules/index.ts';

export interface RoomSeen {
  stateId: number;
  status: string;
  game: Game | null;
  view?: RoomView;
}

export interface Seat {
  readonly client: ProtocolClient;
  readonly player: PlayerRef;
  readonly token: string;
  /** Every message received since the welcome, in order. */
  readonly log: ServerMessage[];
  /** The latest state of each room, from `room` and `shot` messages. */
  readonly rooms: Map<string, RoomSeen>;
}

export function wsUrl(httpUrl: string): string {
  return `${httpUrl.replace(/^http/, 'ws')}/ws`;
}

/** Connects and says hello (with a name, or a token to come back). */
export async function connect(url: string, hello: { name?: string; token?: string }): Promise<Seat> {
  const client = await ProtocolClient.connect(url);
  const log: ServerMessage[] = [];
  const rooms: Seat['rooms'] = new Map();
  client.onMessage((m) => {
    log.push(m);
    if (m.type === 'room') rooms.set(m.room.id, { stateId: m.room.stateId, status: m.room.status, game: m.room.game, view: m.room });
    if (m.type === 'shot') {
      const r = rooms.get(m.room);
      if (!r || r.stateId < m.stateId) rooms.set(m.room, { ...r, stateId: m.stateId, status: r?.status ?? 'playing', game: m.game });
    }
  });
  const welcome = await client.request({ type: 'hello', ...hello });
  if (welcome.type !== 'welcome') throw new Error(`expected a welcome, got ${welcome.type}`);
  return { client, player: welcome.player, token: welcome.token, log, rooms };
}

/** Sends and resolves with the reply, or the error, whichever carries the request back. */
export async function ask(seat: Seat, msg: ClientMessage): Promise<ServerMessage> {
  const id = seat.client.newId();
  const reply = seat.client.waitFor((m) => m.re === id);
  seat.client.send({ ...msg, id });
  return reply;
}

/** Waits until the seat's view of a room reaches at least `stateId`. */
export async function until(seat: Seat, room: string, ok: (r: RoomSeen) => boolean, timeoutMs = 10_000): Promise<void> {
  const t0 = Date.now();
  while (!ok(seat.rooms.get(room) ?? { stateId: -1, status: '', game: null })) {
    if (Date.now() - t0 > timeoutMs) throw new Error(`room ${room} did not reach the expected state in ${timeoutMs} ms`);
    await new Promise((r) => setTimeout(r, 5));
  }
}

/**
 * The player on turn plays the sound bot's shot. The broadcast's outcome must be simulate() of the
 * game it was played from, and its game the rules' judgement of it. Returns the shot message.
 */
export async function playTurn(seat: Seat, roomId: string): Promise<Extract<ServerMessage, { type: 'shot' }>> {
  const r = seat.rooms.get(roomId)!;
  const game = r.game!;
  const shot = chooseShot(game, 'sound', (scene, s) => simulate(scene, s));
  const { player: _player, ...stroke } = shot;
  const reply = await ask(seat, { type: 'shot', room: roomId, stateId: r.stateId, shot: stroke });
  if (reply.type !== 'shot') throw new Error(`shot refused: ${JSON.stringify(reply)}`);
  const from = reply.cueBall ? placeCueBall(game, shot.player, reply.cueBall) : game;
  const outcome = simulate(sceneOf(from), strikeOf(shot));
  expect(reply.outcome.hash).toBe(outcome.hash);
  expect(reply.game).toEqual(JSON.parse(JSON.stringify(applyShot(from, shot, outcome))));
  // A game or frame that ended is followed by the room's new state.
  if (reply.game.winner !== null) await until(seat, roomId, (x) => x.stateId > reply.stateId || x.status === 'over');
  return reply;
}

/** Plays the room's game to its end between two seats; returns the number of shots. */
export async function playToEnd(a: Seat, b: Seat, roomId: string, maxShots = 2000, onShot?: (n: number) => Promise<void>): Promise<number> {
  let shots = 0;
  for (; shots < maxShots; shots++) {
    const r = a.rooms.get(roomId)!;
    if (r.status !== 'playing') break;
    const seat = r.game!.turn === a.player.id ? a : b;
    await until(seat, roomId, (x) => x.stateId === r.stateId);
    await playTurn(seat, roomId);
    // A shot that ends a game comes as two messages (the shot, then the room's new state): wait
    // for both, or the loop reads `playing` between them and plays on in a finished game.
    await until(a, roomId, (x) => x.stateId >= seat.rooms.get(roomId)!.stateId && (x.status !== 'playing' || x.game?.winner === null));
    await onShot?.(shots + 1);
  }
  return shots;
}
