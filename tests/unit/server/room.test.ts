// The room's match steps as pure functions: snooker's race of frames with the break alternating,
// the end of a match, the shot clock's deadline.
import { describe, expect, it } from 'vitest';
import { afterMove, deadlineAfter, gameFor, OVER_KEEP_MS, type RoomState } from '../../../server/game/room.ts';
import { concede, EMPTY_TALLY } from '../../../shared/rules/index.ts';

const base: RoomState = {
  id: 'r1', kind: 'snooker', raceTo: 2, private: false, shotClock: 20, guidance: 'contact', createdBy: 'a',
  seats: [{ id: 'a', name: 'Ann' }, { id: 'b', name: 'Bob' }], status: 'playing', stateId: 1, game: null,
  matchId: 7, order: ['a', 'b'], seed: 42, frame: 0, frames: {}, deadline: null, rematch: [], winner: null, how: null, left: [], closesAt: null, tally: EMPTY_TALLY,
};

describe('a room\'s match', () => {
  it('plays snooker frames until one player has raceTo of them, the break alternating', () => {
    const s0 = { ...base, game: gameFor(base, 0) };
    expect(s0.game.turn).toBe('a');
    // Frame 1 won by b (a concedes the frame on the table's terms: the rules give b the win).
    const s1 = afterMove(s0, concede(s0.game, 'a'), 'played', 1000);
    expect(s1).toMatchObject({ status: 'playing', frame: 1, frames: { b: 1 }, stateId: 2, deadline: 21_000 });
    expect(s1.game!.turn).toBe('b');
    expect(s1.game!.winner).toBeNull();
    const s2 = afterMove(s1, concede(s1.game!, 'b'), 'played', 2000);
    expect(s2).toMatchObject({ status: 'playing', frame: 2, frames: { a: 1, b: 1 } });
    expect(s2.game!.turn).toBe('a');
    const s3 = afterMove(s2, concede(s2.game!, 'b'), 'played', 3000);
    expect(s3).toMatchObject({ status: 'over', winner: 'a', frames: { a: 2, b: 1 }, deadline: null, how: 'played', closesAt: 3000 + OVER_KEEP_MS });
  });

  it('ends the match at once on a concession, in any game', () => {
    const s0 = { ...base, game: gameFor(base, 0) };
    const s1 = afterMove(s0, concede(s0.game, 'a'), 'concession', 1000);
    expect(s1).toMatchObject({ status: 'over', winner: 'b', how: 'concession', frames: { b: 1 } });
    const pool = { ...base, kind: 'nineball' as const, frames: null, raceTo: 3 };
    const p0 = { ...pool, game: gameFor(pool, 0) };
    expect(p0.game.kind === 'nineball' && p0.game.raceTo).toBe(3);
    expect(afterMove(p0, concede(p0.game, 'b'), 'concession', 5)).toMatchObject({ status: 'over', winner: 'a', frames: null });
  });

  it('gives a room stored with a clock under 10 s the 10 s minimum, so the clock cannot foul every tick', () => {
    expect(deadlineAfter({ ...base, shotClock: 0.001 }, 1000)).toBe(11_000);
    expect(deadlineAfter({ ...base, shotClock: 30 }, 1000)).toBe(31_000);
    expect(deadlineAfter({ ...base, shotClock: 0 }, 1000)).toBeNull();
  });
});
