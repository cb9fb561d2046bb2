// Practice runs as the server scores them: a three-cushion run lasts while the player scores (it
// used to end at the first point), and a shot after the run ended is still refused.
import { describe, expect, it } from 'vitest';
import { playShot, practiceRun, practiceStart, RuleError, type Game, type PracticeShot } from '../../../shared/rules/index.ts';

const ME = 'me';

/** The first shot of a fan of headings that scores a point from three-cushion's opening position. */
function firstPoint(start: Game): PracticeShot {
  for (const speed of [3, 4, 5]) {
    for (let i = 0; i < 360; i++) {
      for (const side of [0.3, -0.3]) {
        const shot = { ball: 'white', heading: (i * Math.PI) / 180, speed, side, top: 0 };
        const v = playShot(start, { ...shot, player: ME }).game.verdict!;
        if (!v.foul && v.points[ME] === 1) return { shot };
      }
    }
  }
  throw new Error('no scoring opening shot in the fan');
}

describe('a three-cushion practice run', () => {
  it('goes on after the first point: the player is still at the table and the next shot counts', () => {
    const start = practiceStart('threecushion', ME, 1);
    const point = firstPoint(start);
    const after = practiceRun('threecushion', ME, 1, [point]);
    expect(after.score).toBe(1);
    const last = after.games.at(-1)!;
    expect(last.winner).toBeNull();
    expect(last.turn).toBe(ME);
    // A second shot is played, not refused as coming after the end of the run.
    const miss: PracticeShot = { shot: { ball: 'white', heading: 0, speed: 0.2, side: 0, top: 0 } };
    const run = practiceRun('threecushion', ME, 1, [point, miss]);
    expect(run.games).toHaveLength(2);
    expect(run.games[1]!.verdict!.player).toBe(ME);
    // That miss ended the inning, and so the run: a third shot is refused.
    expect(() => practiceRun('threecushion', ME, 1, [point, miss, miss])).toThrow(RuleError);
    expect(() => practiceRun('threecushion', ME, 1, [point, miss, miss])).toThrow(/shots\[2\]: the run ended/);
  });

  it('is a race no run of allowed length reaches', () => {
    const g = practiceStart('threecushion', ME, 1);
    expect(g.kind === 'threecushion' && g.raceTo).toBeGreaterThan(500);
    // Nine-ball stays one rack: a run-out from the break.
    const n = practiceStart('nineball', ME, 1);
    expect(n.kind === 'nineball' && n.raceTo).toBe(1);
  });
});
