// playShot (place, simulate, judge) and the shot clock's foul, for every game.
import { describe, expect, it } from 'vitest';
import { simulate } from '../../../shared/physics/index.ts';
import { applyShot, newGame, placeCueBall, playShot, RuleError, sceneOf, shotClockExpired, strikeOf } from '../../../shared/rules/index.ts';

describe('playShot', () => {
  it('is placeCueBall, then simulate(sceneOf) and applyShot: the one way a shot is played', () => {
    const g = newGame('nineball', ['a', 'b'], { seed: 5 });
    const shot = { player: 'a', ball: 'cue', heading: 0.02, speed: 7, side: 0, top: 0.1 };
    const at = { x: -0.9, y: 0.2 };
    const played = playShot(g, shot, at);
    const from = placeCueBall(g, 'a', at);
    const outcome = simulate(sceneOf(from), strikeOf(shot));
    expect(played.from).toEqual(from);
    expect(played.outcome.hash).toBe(outcome.hash);
    expect(played.game).toEqual(applyShot(from, shot, outcome));
  });

  it('throws and changes nothing on an illegal placement or a miscue', () => {
    const g = newGame('nineball', ['a', 'b'], { seed: 5 });
    const copy = structuredClone(g);
    expect(() => playShot(g, { player: 'a', ball: 'cue', heading: 0, speed: 7, side: 0, top: 0 }, { x: 0.5, y: 0 })).toThrow(RuleError);
    expect(() => playShot(g, { player: 'a', ball: 'cue', heading: 0, speed: 7, side: 0.4, top: 0.4 })).toThrow(/miscue/);
    expect(g).toEqual(copy);
  });
});

describe('shotClockExpired', () => {
  it.each(['nineball', 'eightball', 'snooker', 'threecushion'] as const)('gives %s\'s own foul for a stroke that meets nothing, and passes the turn', (kind) => {
    const g = newGame(kind, ['a', 'b'], { seed: 2 });
    const next = shotClockExpired(g);
    expect(next.turn).toBe('b');
    expect(next.verdict).toMatchObject({ player: 'a', foul: true, reason: 'no-contact', message: expect.stringMatching(/^a ran out of time/) });
    // Nothing moved (a cue ball in hand may be put at the usual spot for the opponent).
    const objects = (balls: typeof g.balls) => balls.filter((b) => b.id !== 'cue').sort((x, y) => x.id.localeCompare(y.id));
    expect(objects(next.balls)).toEqual(objects(g.balls));
    if (kind === 'nineball') expect(next.ballInHand).toBe('anywhere');
    if (kind === 'snooker') expect(next.scores.b).toBe(4);
  });
});
