// The verdict in words: names where the rules put players, never for ball numbers or points.
import { describe, expect, it } from 'vitest';
import { inWords } from '../../../client/verdict.ts';

const names = (id: string) => ({ '1': 'Ann', '5': 'Bob' })[id];

describe('inWords', () => {
  it('names the players and says the fouls plainly, leaving balls and points alone, as a sentence', () => {
    expect(inWords('foul by 1 (no-rail): 5 has ball in hand', names)).toBe('Foul by Ann (no rail after contact): Bob has ball in hand');
    expect(inWords('5 pockets 1, 5 and continues', names)).toBe('Bob pockets 1, 5 and continues');
    expect(inWords('1 pots red1 for 1 (break 5)', names)).toBe('Ann pots a red for 1 (break 5)');
    expect(inWords('foul by 5 (in-off, no-contact): 4 to 1', names)).toBe('Foul by Bob (in-off, no ball hit): 4 to Ann');
    expect(inWords('point for 1 (3 cushions before the second ball; run 2)', names)).toBe('Point for Ann (3 cushions before the second ball; run 2)');
    expect(inWords('5 ran out of time: foul by 5 (no-contact): 1 has ball in hand', names)).toBe('Bob ran out of time: foul by Bob (no ball hit): Ann has ball in hand');
    expect(inWords('1 claims the game: 5 has left; 1 wins', names)).toBe('Ann claims the game: Bob has left; Ann wins');
    expect(inWords('illegal break by 1: 5 may play on, re-rack and break, or have 1 break again', names)).toBe(
      'Illegal break by Ann: Bob may play on, re-rack and break, or have Ann break again',
    );
  });
});
