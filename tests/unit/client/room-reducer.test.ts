// The room page's reducer: server messages and the player's input make the next state, with no
// DOM and no clock.
import { describe, expect, it } from 'vitest';
import { reduce, type RoomAction, type ShotMessage } from '../../../client/room/reducer.ts';
import { clockLeft, resultView, verdictText } from '../../../client/room/render.ts';
import { concedeArmed, CONFIRM_MS, initialRoomState, myTurn, type RoomPageState } from '../../../client/room/state.ts';
import type { RoomView } from '../../../shared/protocol/index.ts';
import { newGame, playShot, type Game } from '../../../shared/rules/index.ts';

const roomView = (extra: Partial<RoomView> = {}): RoomView => ({
  id: 'r', kind: 'nineball', raceTo: 3, private: false, shotClock: 30, guidance: 'contact', spectators: 0, status: 'playing', stateId: 1,
  game: newGame('nineball', ['a', 'b'], { seed: 1 }), match: 7,
  players: [{ id: 'a', name: 'Ann', connected: true }, { id: 'b', name: 'Bob', connected: true }], ...extra,
});

const run = (s: RoomPageState, ...actions: RoomAction[]) => actions.reduce(reduce, s);
const start = (me = 'a', room = roomView()) => run(initialRoomState('r', me), { type: 'room', room });

/** The break, played from `game` by its player on turn: the broadcast that says so. */
function broadcast(game: Game, stateId: number, re?: number): ShotMessage {
  const shot = { ball: 'cue', heading: 0, speed: 8, side: 0, top: 0, player: game.turn };
  const played = playShot(game, shot);
  return { type: 'shot', room: 'r', match: 7, stateId, shot, outcome: { hash: played.outcome.hash, balls: [], events: [], duration: 1 }, game: played.game, deadline: 12345, ...(re !== undefined ? { re } : {}) };
}

describe('room page reducer', () => {
  it('takes the room and its game; never mutates the state it was given', () => {
    const s0 = initialRoomState('r', 'a');
    const frozen = JSON.stringify(s0);
    const s = reduce(s0, { type: 'room', room: roomView() });
    expect(JSON.stringify(s0)).toBe(frozen);
    expect(s.game).toEqual(roomView().game);
    expect(s.stateId).toBe(1);
    expect(reduce(s0, { type: 'room', room: roomView({ id: 'other' }) })).toBe(s0);
  });

  it('holds a room message that comes during an animation and applies it after', () => {
    const s = run(start(), { type: 'animating' });
    const over = roomView({ status: 'over', winner: 'a', stateId: 1, rematch: ['b'] });
    const held = reduce(s, { type: 'room', room: over });
    expect(held.room?.status).toBe('playing');
    expect(held.pendingRoom).toBe(over);
    const after = reduce(held, { type: 'animated' });
    expect(after.room).toBe(over);
    expect(after.pendingRoom).toBeNull();
  });

  it('a broadcast shot adopts the server\'s game and its verdict\'s "how" (the stroke)', () => {
    const s = start('b');
    const m = broadcast(s.game!, 2);
    const n = reduce(s, m);
    expect(n.game).toBe(m.game);
    expect(n.stateId).toBe(2);
    expect(n.deadline).toBe(12345);
    expect(n.how).toEqual({ action: 'shot', shot: m.shot, before: s.game });
    // A gap (a missed message) takes the server's state as it is, without the stroke.
    const gap = reduce(s, { ...m, stateId: 5 });
    expect(gap.stateId).toBe(5);
    expect(gap.how.action).not.toBe('shot');
  });

  it('this page\'s shot: busy until it has played; the server\'s answer adopted, a refusal said', () => {
    const s = start('a');
    expect(myTurn(s)).toBe(true);
    const sent = reduce(s, { type: 'shot-sent' });
    expect(sent.busy).toBe(true);
    expect(myTurn(sent)).toBe(false);
    const m = broadcast(s.game!, 2, 1);
    const answered = reduce(sent, { type: 'shot-reply', message: m });
    expect(answered.game).toBe(m.game);
    expect(answered.how.action).toBe('shot');
    expect(reduce(answered, { type: 'shot-done' }).busy).toBe(false);
    const refused = run(sent, { type: 'shot-reply', message: { type: 'error', re: 1, code: 'stale', message: 'stale state' } as never }, { type: 'shot-done', refused: 'stale state' });
    expect(refused.game).toBe(s.game);
    expect(refused.notice).toBe('The server refused the shot: stale state');
  });

  it('no shot when it is not the player\'s turn, nor for a spectator, nor while reconnecting', () => {
    const b = start('b');
    expect(reduce(b, { type: 'shot-sent' })).toBe(b);
    const watcher = start('z');
    expect(reduce(watcher, { type: 'shot-sent' })).toBe(watcher);
    const down = reduce(start('a'), { type: 'session', me: 'a', reconnecting: true });
    expect(reduce(down, { type: 'shot-sent' })).toBe(down);
  });

  it('concede needs two clicks within the confirm window', () => {
    const s = start('a');
    const once = reduce(s, { type: 'concede', now: 1000 });
    expect(once.concededAt).toBeUndefined();
    expect(concedeArmed(once, 1000 + CONFIRM_MS - 1)).toBe(true);
    expect(reduce(once, { type: 'concede', now: 3000 }).concededAt).toBe(3000);
    // Too late: the second click only arms it again.
    const late = reduce(once, { type: 'concede', now: 1000 + CONFIRM_MS + 1 });
    expect(late.concededAt).toBeUndefined();
    expect(concedeArmed(late, 1000 + CONFIRM_MS + 2)).toBe(true);
    // A spectator has nothing to concede.
    const watcher = start('z');
    expect(reduce(watcher, { type: 'concede', now: 1 })).toBe(watcher);
  });

  it('a refused chat line sets the note; sending again clears it; chat lines are kept', () => {
    const s = run(start(), { type: 'chat-sent', id: '4' }, { type: 'chat', room: 'r', from: { id: 'b', name: 'Bob' }, text: 'hi', at: 0 });
    expect(s.chat).toEqual([{ from: 'Bob', text: 'hi' }]);
    const refused = reduce(s, { type: 'error', re: 4, code: 'rate-limited', message: 'too fast' });
    expect(refused.chatNote).toBe('Too fast.');
    expect(refused.chatSent).toEqual([]);
    expect(reduce(refused, { type: 'chat-sent' }).chatNote).toBe('');
    // Another error is not the chat's.
    expect(reduce(s, { type: 'error', re: 9, code: 'rate-limited', message: 'x' }).chatNote).toBe('');
  });

  it('an unknown room is missing; ratings are wanted before a match and after a rated one', () => {
    expect(reduce(initialRoomState('r'), { type: 'error', code: 'no-room', message: 'no such room' }).missing).toBe(true);
    const s = start();
    expect(s.ratedBefore).toBe(7);
    const rated = run(s, { type: 'rating', match: 7, player: 'a', when: 'before', rating: 1500 }, { type: 'room', room: roomView({ status: 'over', rated: true, winner: 'a' }) });
    expect(rated.ratedAfter).toBe(7);
    expect(rated.ratings).toEqual({ a: { before: 1500 } });
    expect(reduce(rated, { type: 'rating', match: 6, player: 'b', when: 'after', rating: 1 })).toBe(rated);
  });
});

describe('room page render (words from the state alone)', () => {
  it('the referee\'s line: waiting, to break, a notice, and an ended match not rated', () => {
    expect(verdictText(start('a', roomView({ status: 'waiting', game: null, stateId: 0 })))).toBe('Waiting for an opponent.');
    const s = start('a');
    expect(verdictText(s)).toBe('Ann to break.');
    expect(verdictText(reduce(s, { type: 'notice', text: 'Call a pocket for the 8 first.' }))).toBe('Call a pocket for the 8 first.');
    const over = start('a', roomView({ status: 'over', winner: 'b', rated: false, unrated: 'too short' }));
    expect(verdictText(over)).toBe('Bob wins. Not rated: too short.');
    expect(resultView(over)?.seated).toBe(true);
    expect(resultView(s)).toBeNull();
  });

  it('the shot clock shows full while the last shot\'s balls roll, and nothing once over', () => {
    const s = { ...start('a'), deadline: 100_000 };
    expect(clockLeft(s, 0)).toBe(30);
    expect(clockLeft(s, 90_500)).toBe(10);
    expect(clockLeft(s, 200_000)).toBe(0);
    expect(clockLeft({ ...s, room: { ...s.room!, status: 'over' } }, 0)).toBeNull();
  });

  it('the result dialog\'s key changes when a rematch is asked, not otherwise', () => {
    const over = start('a', roomView({ status: 'over', winner: 'a', rated: false }));
    const again = reduce(over, { type: 'room', room: roomView({ status: 'over', winner: 'a', rated: false, spectators: 3 }) });
    expect(resultView(again)?.key).toBe(resultView(over)?.key);
    const asked = reduce(over, { type: 'room', room: roomView({ status: 'over', winner: 'a', rated: false, rematch: ['b'] }) });
    expect(resultView(asked)?.note).toBe('Bob asks for a rematch.');
    expect(resultView(asked)?.key).not.toBe(resultView(over)?.key);
  });
});
