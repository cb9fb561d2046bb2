// The tray of pocketed balls: from the game's state, in the order the balls went down.
import { describe, expect, it } from 'vitest';
import { newGame, type Game } from '../../../shared/rules/index.ts';
import { pocketedBalls, rackOf } from '../../../client/table/tray.ts';

const without = (g: Game, ids: string[]): Game => ({ ...g, balls: g.balls.filter((b) => !ids.includes(b.id)) }) as Game;

describe('pocketedBalls', () => {
  it('lists the rack\'s balls not on the table, never the cue ball, in the order they went down', () => {
    const g = newGame('nineball', ['a', 'b']);
    expect(rackOf(g)).toEqual(['1', '2', '3', '4', '5', '6', '7', '8', '9']);
    expect(pocketedBalls(g)).toEqual([]);
    const down = without(g, ['cue', '7', '3']);
    expect(pocketedBalls(down, ['7', '3'])).toEqual(['7', '3']);
    expect(pocketedBalls(down, ['3', '7'])).toEqual(['3', '7']);
    // Down before this page saw them (a reconnect): rack order, ahead of those it saw.
    expect(pocketedBalls(without(g, ['7', '3', '5']), ['5'])).toEqual(['3', '7', '5']);
  });

  it('a ball spotted again leaves the tray; snooker\'s reds and colours, carom none', () => {
    const s = newGame('snooker', ['a', 'b']);
    expect(pocketedBalls(without(s, ['red4', 'pink']), ['red4', 'pink'])).toEqual(['red4', 'pink']);
    expect(pocketedBalls(s, ['red4', 'pink'])).toEqual([]);
    expect(rackOf(newGame('threecushion', ['a', 'b']))).toEqual([]);
    expect(rackOf(newGame('practice', ['me'], { layout: 'eightball' }))).toHaveLength(15);
    expect(rackOf(newGame('practice', ['me'], { layout: 'empty' }))).toEqual([]);
  });
});
