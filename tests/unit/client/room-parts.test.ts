// The room page's pure parts: the scoreboard's numbers, the result dialog's words, the aim's
// first ball and its warning, and what made a verdict.
import { describe, expect, it } from 'vitest';
import { howOf } from '../../../client/room/state.ts';
import { resultContent } from '../../../client/room/result.ts';
import { caromAverage, scoreLines, snookerPointsLeft } from '../../../client/room/scoreboard.ts';
import { contactWarning, firstBallAlong } from '../../../client/room/targets.ts';
import type { RoomView } from '../../../shared/protocol/index.ts';
import { concede, newGame, shotClockExpired, type Game } from '../../../shared/rules/index.ts';

const name = (id: string) => ({ a: 'Ann', b: 'Bob' })[id] ?? id;

describe('scoreboard numbers', () => {
  it('snooker: 15 reds and the colours are 147; after a red, 7 more for the colour', () => {
    const g = newGame('snooker', ['a', 'b']);
    expect(snookerPointsLeft(g)).toBe(147);
    const noRed = { ...g, balls: g.balls.filter((b) => b.id !== 'red1'), on: 'colour' } as Game;
    expect(snookerPointsLeft(noRed)).toBe(14 * 8 + 27 + 7);
    const end = { ...g, balls: g.balls.filter((b) => b.id === 'cue' || b.id === 'pink' || b.id === 'black'), on: 'pink' } as Game;
    expect(snookerPointsLeft(end)).toBe(13);
    expect(scoreLines(g, name)).toContainEqual({ label: 'Points left', value: '147' });
    expect(scoreLines(g, name)).toContainEqual({ label: 'Ball on', value: 'a red' });
  });
  it('pool: the ball on and the balls left; eight-ball groups', () => {
    const nine = newGame('nineball', ['a', 'b']);
    expect(scoreLines(nine, name)).toEqual([{ label: 'Ball on', value: 'the 1' }, { label: 'Balls left', value: '9' }]);
    const eight = { ...newGame('eightball', ['a', 'b']), groups: { a: 'stripes', b: 'solids' } } as Game;
    expect(scoreLines(eight, name)).toEqual([{ label: 'Ann', value: 'stripes, 7 left' }, { label: 'Bob', value: 'solids, 7 left' }]);
  });
  it('three-cushion: innings and the average', () => {
    expect(caromAverage(7, 4)).toBe('1.750');
    expect(caromAverage(0, 0)).toBe('0.000');
    const g = { ...newGame('threecushion', ['a', 'b']), scores: { a: 3, b: 1 }, innings: { a: 2, b: 2 } } as Game;
    expect(scoreLines(g, name)[0]).toEqual({ label: 'Ann', value: '3 in 2 innings, average 1.500, high run 0' });
  });
});

const over = (extra: Partial<RoomView>): RoomView => ({
  id: 'r', kind: 'nineball', raceTo: 3, private: false, shotClock: 0, guidance: 'contact', spectators: 0, status: 'over', stateId: 9, game: null,
  players: [{ id: 'a', name: 'Ann', connected: true }, { id: 'b', name: 'Bob', connected: true }], winner: 'a', ...extra,
});

describe('result dialog content', () => {
  it('the winner, the racks and the rating change', () => {
    const game = { ...newGame('nineball', ['a', 'b']), scores: { a: 3, b: 1 }, winner: 'a' } as Game;
    const c = resultContent(over({ rated: true }), game, name, { a: { before: 1500, after: 1516.4 }, b: { before: 1500, after: 1484 } });
    expect(c).toEqual({ heading: 'Ann wins', score: 'Ann 3 – 1 Bob (racks)', rating: ['Ann: 1500 → 1516 (+16)', 'Bob: 1500 → 1484 (−16)'] });
    expect(resultContent(over({ rated: true }), game, name, {}, 'a').heading).toBe('You win');
  });
  it('not rated, with the reason; snooker frames', () => {
    const c = resultContent(over({ kind: 'snooker', rated: false, unrated: 'each player must take at least 3 shots', frames: { a: 1, b: 0 } }), null, name);
    expect(c.score).toBe('Ann 1 – 0 Bob (frames)');
    expect(c.rating).toEqual(['Not rated: each player must take at least 3 shots.']);
  });
});

describe('aim warning', () => {
  const R = 0.028575;
  const balls = [{ id: 'cue', x: 0, y: 0 }, { id: '9', x: 0.5, y: 0.01 }, { id: '1', x: 1, y: 0 }, { id: '2', x: -0.5, y: 0 }];
  it('finds the first ball along the line, ahead only', () => {
    expect(firstBallAlong({ x: 0, y: 0 }, 0, balls, 'cue', R)).toBe('9');
    expect(firstBallAlong({ x: 0, y: 0 }, Math.PI, balls, 'cue', R)).toBe('2');
    expect(firstBallAlong({ x: 0, y: 0 }, Math.PI / 2, balls, 'cue', R)).toBeNull();
  });
  it('warns when the first ball is not on', () => {
    expect(contactWarning('9', ['1'])).toBe('Illegal: the 9 is not the ball on (hit the 1 first).');
    expect(contactWarning('1', ['1'])).toBe('');
    expect(contactWarning(null, ['1'])).toBe('');
    expect(contactWarning('pink', ['red1', 'red2'])).toBe('Illegal: the pink is not the ball on (hit a red first).');
  });
});

describe('what made a verdict', () => {
  it('a stroke, the clock, a concession, a claim, a choice', () => {
    const g = newGame('nineball', ['a', 'b']);
    const clock = shotClockExpired(g);
    expect(howOf(g, clock)?.action).toBe('clock');
    expect(howOf(g, clock, { pushOut: true })?.shot).toEqual({ pushOut: true });
    expect(howOf(g, concede(g, 'a'))?.action).toBe('concede');
    expect(howOf(g, concede(g, 'a'), undefined, true)?.action).toBe('claim');
    expect(howOf(clock, { ...clock })).toBeNull();
  });
});
