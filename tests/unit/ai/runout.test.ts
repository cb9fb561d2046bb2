// Level 5 runs out a fixed nine-ball rack: after a level-5 break on seed RACK, with ball in hand,
// it wins the rack without the opponent shooting.
import { describe, expect, it } from 'vitest';
import { chooseShot } from '../../../shared/ai/index.ts';
import { newGame, type Game } from '../../../shared/rules/index.ts';
import { apply } from './support.ts';

const RACK = 2;

describe('level 5 at nine-ball', () => {
  it('runs out a fixed rack from ball in hand', () => {
    let g = newGame('nineball', ['a', 'b'], { seed: RACK });
    g = apply(g, chooseShot(g, { level: 5, seed: RACK }));
    expect(g.winner).toBeNull();
    g = { ...g, turn: 'a', ballInHand: 'anywhere', phase: 'play', choices: [], verdict: null } as Game;
    const shooters: string[] = [];
    for (let i = 0; i < 20 && g.winner === null; i++) {
      shooters.push(g.turn);
      g = apply(g, chooseShot(g, { level: 5, seed: 100 + i }));
    }
    expect(g.winner).toBe('a');
    expect(shooters.every((p) => p === 'a')).toBe(true);
  }, 120_000);
});
