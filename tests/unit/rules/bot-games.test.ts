// Whole games played to the end by the bot through the real simulate(): they terminate, the
// points add up shot by shot, and the right player wins.
import { describe, expect, it } from 'vitest';
import { simulate } from '../../../shared/physics/index.ts';
import { newGame, type Game } from '../../../shared/rules/index.ts';
import { playToEnd, type Simulate } from '../../../bots/strategy.ts';

const play: Simulate = (scene, shot) => simulate(scene, shot);

const sum = (r: Record<string, number>): number => Object.values(r).reduce((a, b) => a + b, 0);
const seeds = [1, 2, 3, 4];

function pointsAddUp(history: Game[]): void {
  for (let i = 1; i < history.length; i++) {
    const v = history[i]!.verdict!;
    expect(sum(history[i]!.scores) - sum(history[i - 1]!.scores)).toBe(sum(v.points));
  }
}

describe('whole games by a simple bot through simulate()', () => {
  it.each(seeds)('nine-ball race to 3 ends, the winner has 3 racks (seed %i)', (seed) => {
    const { game, history } = playToEnd(newGame('nineball', ['a', 'b'], { seed, raceTo: 3 }), play);
    expect(game.winner).not.toBeNull();
    expect(game.scores[game.winner!]).toBe(3);
    expect(sum(game.scores)).toBeLessThanOrEqual(5);
    pointsAddUp(history);
  });

  it.each(seeds)('eight-ball race to 2 ends, the winner has 2 racks (seed %i)', (seed) => {
    const { game, history } = playToEnd(newGame('eightball', ['a', 'b'], { seed, raceTo: 2 }), play);
    expect(game.winner).not.toBeNull();
    expect(game.scores[game.winner!]).toBe(2);
    pointsAddUp(history);
  });

  it.each(seeds)('a snooker frame ends with every ball potted or a foul on the last black; the higher score wins (seed %i)', (seed) => {
    const { game, history } = playToEnd(newGame('snooker', ['a', 'b'], { seed }), play);
    expect(game.winner).not.toBeNull();
    const loser = game.players.find((p) => p !== game.winner)!;
    expect(game.scores[game.winner!]).toBeGreaterThan(game.scores[loser]!);
    expect(game.balls.filter((b) => b.id !== 'cue' && b.id !== 'black')).toEqual([]);
    pointsAddUp(history);
  });

  it.each(seeds)('three-cushion race to 5 ends at exactly 5 for the winner (seed %i)', (seed) => {
    const { game, history } = playToEnd(newGame('threecushion', ['a', 'b'], { seed, raceTo: 5 }), play);
    expect(game.winner).not.toBeNull();
    expect(game.scores[game.winner!]).toBe(5);
    for (const p of game.players) if (p !== game.winner) expect(game.scores[p]).toBeLessThan(5);
    pointsAddUp(history);
  });
});
