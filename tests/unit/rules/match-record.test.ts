// Match records replayed with the shared rules and physics, and the achievements read from them.
import { describe, expect, it } from 'vitest';
import { botShot } from '../../../bots/strategy.ts';
import { simulate } from '../../../shared/physics/index.ts';
import {
  achievements,
  claimGame,
  concede,
  newGame,
  placeCueBall,
  playShot,
  replayMatch,
  shotClockExpired,
  type Game,
  type GameKind,
  type MatchAction,
} from '../../../shared/rules/index.ts';

/** A whole game by the sound bot, as a record of shot actions with their hashes. */
function botGame(kind: Exclude<GameKind, 'practice'>, seed: number, raceTo = 1): { start: Game; actions: MatchAction[]; games: Game[] } {
  const start = newGame(kind, ['a', 'b'], { seed, raceTo });
  const actions: MatchAction[] = [];
  const games: Game[] = [];
  let g = start;
  while (g.winner === null && actions.length < 400) {
    const { shot } = botShot(g, (scene, s) => simulate(scene, s));
    const played = playShot(g, shot);
    const { player, ...stroke } = shot;
    actions.push({ type: 'shot', player, shot: stroke, hash: played.outcome.hash });
    g = played.game;
    games.push(g);
  }
  return { start, actions, games };
}

describe('replayMatch', () => {
  it('replays a recorded game to the same games and hashes', () => {
    const rec = botGame('eightball', 4);
    const r = replayMatch(rec);
    expect(r.games).toEqual(rec.games);
    expect(r.shots.map((s) => s.hash)).toEqual(rec.actions.map((a) => (a.type === 'shot' ? a.hash : '')));
    expect(r.shots.every((s) => s.recorded === s.hash)).toBe(true);
  });

  it('replays placements, the clock, claims, concessions and snooker frames as the rules do', () => {
    const start = newGame('nineball', ['a', 'b'], { seed: 3 });
    const foul = { ball: 'cue', heading: Math.PI, speed: 0.05, side: 0, top: 0 };
    const actions: MatchAction[] = [
      { type: 'shot', player: 'a', shot: foul },
      { type: 'place', player: 'b', cueBall: { x: 0.2, y: 0.3 } },
      { type: 'clock', player: 'b' },
      { type: 'claim', player: 'a' },
    ];
    let g = playShot(start, { ...foul, player: 'a' }).game;
    g = placeCueBall(g, 'b', { x: 0.2, y: 0.3 });
    g = shotClockExpired(g);
    g = claimGame(g, 'a');
    expect(replayMatch({ start, actions }).game).toEqual(g);
    expect(g.winner).toBe('a');
    // A claim is scored as the absent player's concession and said as a claim.
    expect(g).toEqual({ ...concede(shotClockExpired(placeCueBall(playShot(start, { ...foul, player: 'a' }).game, 'b', { x: 0.2, y: 0.3 })), 'b'), verdict: g.verdict });
    expect(g.verdict).toMatchObject({ loss: 'concession', rackWinner: 'a', message: 'a claims the game: b has left; a wins' });
    const frame = replayMatch({ start: newGame('snooker', ['a', 'b']), actions: [{ type: 'concede', player: 'a' }, { type: 'frame', players: ['b', 'a'], seed: 9 }] });
    expect(frame.game).toEqual(newGame('snooker', ['b', 'a'], { seed: 9 }));
  });

  it('refuses a record whose action the rules refuse', () => {
    const start = newGame('nineball', ['a', 'b'], { seed: 3 });
    expect(() => replayMatch({ start, actions: [{ type: 'shot', player: 'b', shot: { ball: 'cue', heading: 0, speed: 3, side: 0, top: 0 } }] })).toThrow(/turn/);
  });
});

describe('achievements', () => {
  it('gives each snooker player their highest break, and three-cushion players their longest run', () => {
    const s = botGame('snooker', 2);
    const best = new Map<string, number>();
    for (const g of s.games) {
      const v = g.verdict!;
      if (g.kind === 'snooker' && !v.foul && (v.points[v.player] ?? 0) > 0) best.set(v.player, Math.max(best.get(v.player) ?? 0, g.break));
    }
    expect(best.size).toBeGreaterThan(0);
    expect(achievements(s.start, s.games).sort((x, y) => x.player.localeCompare(y.player))).toEqual(
      [...best].sort().map(([player, value]) => ({ player, what: 'break', value })),
    );
    const c = botGame('threecushion', 1, 4);
    const last = c.games.at(-1)!;
    if (last.kind !== 'threecushion') throw new Error('not carom');
    const runs = achievements(c.start, c.games);
    for (const p of ['a', 'b']) expect(runs.find((x) => x.player === p)?.value ?? 0).toBe(last.highRun[p]);
  });

  it('records a nine-ball rack won by its breaker without the opponent playing, and no other', () => {
    let found = 0;
    for (let seed = 1; seed <= 12; seed++) {
      const rec = botGame('nineball', seed);
      const got = achievements(rec.start, rec.games);
      const cleanWin = rec.games.every((g) => g.verdict!.player === 'a') && rec.games.at(-1)!.winner === 'a';
      expect(got).toEqual(cleanWin ? [{ player: 'a', what: 'break-and-run', value: rec.games.length }] : []);
      if (cleanWin) found++;
    }
    expect(found).toBeGreaterThan(0);
  });
});
