// The verdict in words, built from the Verdict's fields and the Game: names only where players
// are, ball numbers and points as they are, the pocket as the screen names it, "You" with its verbs.
import { describe, expect, it } from 'vitest';
import { verdictSentence } from '../../../client/verdict.ts';
import { applyShot, claimGame, concede, decide, newGame, shotClockExpired, type Game, type Outcome, type Shot } from '../../../shared/rules/index.ts';

// Ids that look like numbers, as the server's player ids do: the old text editing took them for players.
const names = (id: string) => ({ '4': 'Ann', '5': 'Bob' })[id] ?? `?${id}`;

/** An outcome: the cue ball meets `first`, a cushion after, and `pots` go down (in the given pockets). */
function outcome(game: Game, first: string | null, pots: Record<string, string> = {}, cushions = 1): Outcome {
  const events = [
    ...(first ? [{ t: 1, kind: 'ball', balls: ['cue', first] }] : []),
    ...Array.from({ length: cushions }, (_, i) => ({ t: 2 + i, kind: 'cushion', balls: [first ?? 'cue'] })),
    ...Object.entries(pots).map(([id, pocket], i) => ({ t: 5 + i, kind: 'pocket', balls: [id], pocket })),
  ];
  return { balls: game.balls.map((b) => ({ id: b.id, x: b.x, y: b.y, pocketed: id(b.id, pots), ...(pots[b.id] ? { pocket: pots[b.id] } : {}) })), events };
}
const id = (ball: string, pots: Record<string, string>) => pots[ball] !== undefined;
const stroke = (player: string, extra: Partial<Shot> = {}): Shot => ({ player, ball: 'cue', heading: 0, speed: 2, side: 0, top: 0, ...extra });

function nine(): Game {
  return { ...newGame('nineball', ['4', '5'], { seed: 1 }), phase: 'play' } as Game;
}

describe('verdictSentence: nine-ball', () => {
  it('says the pots with "the" and continues', () => {
    const g = applyShot(nine(), stroke('4'), outcome(nine(), '1', { '1': 'TL', '6': 'BL' }));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Ann pockets the 1 and the 6 and continues.');
  });
  it('says "you" with the verbs to match (defect 3)', () => {
    const g = applyShot(nine(), stroke('4'), outcome(nine(), '1', { '1': 'TL' }));
    expect(verdictSentence(g, g.verdict!, names, { me: '4' })).toBe('You pocket the 1 and continue.');
    const won = applyShot(nine(), stroke('4'), outcome(nine(), '1', { '9': 'TL' }));
    expect(verdictSentence(won, won.verdict!, names, { me: '4' })).toBe('You pocket the 9 and win the game.');
  });
  it('a foul names the fouler, the fouls, and who has ball in hand', () => {
    const g = applyShot(nine(), stroke('4'), outcome(nine(), null, {}, 0));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Foul by Ann (no ball hit): Bob has ball in hand.');
  });
  it('a shot clock run-out says the time, not "no ball hit" (defect 3)', () => {
    const g = shotClockExpired(nine());
    expect(verdictSentence(g, g.verdict!, names, { action: 'clock' })).toBe('Ann ran out of time: Bob has ball in hand.');
    const snooker = shotClockExpired(newGame('snooker', ['4', '5'], { seed: 1 }));
    expect(verdictSentence(snooker, snooker.verdict!, names, { action: 'clock' })).toBe('Ann ran out of time: 4 points to Bob; ball on: a red.');
    const carom = shotClockExpired(newGame('threecushion', ['4', '5'], { seed: 1 }));
    expect(verdictSentence(carom, carom.verdict!, names, { action: 'clock' })).toBe('Ann ran out of time; Bob to play.');
  });
  it('a push-out', () => {
    const g0 = { ...nine(), phase: 'push-out' } as Game;
    const g = applyShot(g0, stroke('4', { pushOut: true }), outcome(g0, null, {}, 0));
    expect(verdictSentence(g, g.verdict!, names, { shot: { pushOut: true } })).toBe('Ann pushes out; Bob may shoot or pass the shot back.');
    const passed = decide(g, '5', 'pass');
    expect(verdictSentence(passed, passed.verdict!, names, { action: 'decide', choice: 'pass' })).toBe('Bob passes: Ann to play.');
  });
  it('a miss', () => {
    const g = applyShot(nine(), stroke('4'), outcome(nine(), '1'));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Ann misses; Bob to play.');
  });
});

describe('verdictSentence: eight-ball', () => {
  it('says the called pocket as the screen names it (defect 2)', () => {
    const start = newGame('eightball', ['4', '5'], { seed: 1 });
    // Only the 8 is left of Ann's: every solid is gone.
    const g0 = { ...start, phase: 'play', groups: { '4': 'solids', '5': 'stripes' }, balls: start.balls.filter((b) => !['1', '2', '3', '4', '5', '6', '7'].includes(b.id)) } as Game;
    const g = applyShot(g0, stroke('4', { calledPocket: 'TL', calledBall: '8' }), outcome(g0, '8', { '8': 'TL' }));
    expect(verdictSentence(g, g.verdict!, names, { shot: { calledPocket: 'TL' } })).toBe('Ann pockets the 8 in the called upper right corner and wins the game.');
  });
  it('the groups taken on an open table', () => {
    const start = newGame('eightball', ['4', '5'], { seed: 1 });
    const g0 = { ...start, phase: 'play' } as Game;
    const g = applyShot(g0, stroke('4'), outcome(g0, '3', { '3': 'BL' }));
    expect(verdictSentence(g, g.verdict!, names, { before: g0 })).toBe('Ann pockets the 3 and takes the solids.');
  });
});

describe('verdictSentence: snooker', () => {
  it('a foul says the penalty in points, not a name (defect 1)', () => {
    const g0 = newGame('snooker', ['4', '5'], { seed: 1 });
    const g = applyShot(g0, stroke('4'), outcome(g0, null, {}, 0));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Foul by Ann (no ball hit): 4 points to Bob; ball on: a red.');
  });
  it('a pot with its points and the break', () => {
    const g0 = { ...newGame('snooker', ['4', '5'], { seed: 1 }), shots: 3 } as Game;
    const g = applyShot(g0, stroke('4'), outcome(g0, 'red1', { red1: 'TL' }));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Ann pots a red for 1 (break 1); ball on: a colour.');
  });
});

describe('verdictSentence: more of eight-ball and snooker', () => {
  it('the 8 in another pocket than the called one loses the rack', () => {
    const start = newGame('eightball', ['4', '5'], { seed: 1 });
    const g0 = { ...start, phase: 'play', groups: { '4': 'solids', '5': 'stripes' }, balls: start.balls.filter((b) => !['1', '2', '3', '4', '5', '6', '7'].includes(b.id)) } as Game;
    const g = applyShot(g0, stroke('4', { calledPocket: 'TL', calledBall: '8' }), outcome(g0, '8', { '8': 'BL' }));
    expect(verdictSentence(g, g.verdict!, names, { shot: { calledPocket: 'TL' } })).toBe('Ann pockets the 8 in another pocket than the called upper right corner and loses the game.');
  });
  it('the black potted last wins the frame, with its score', () => {
    const start = newGame('snooker', ['4', '5'], { seed: 1 });
    const g0 = { ...start, shots: 40, on: 'black', scores: { '4': 53, '5': 50 }, balls: start.balls.filter((b) => b.id === 'cue' || b.id === 'black') } as Game;
    const g = applyShot(g0, stroke('4'), outcome(g0, 'black', { black: 'TL' }));
    expect(verdictSentence(g, g.verdict!, names)).toBe('Ann pots the black for 7 (break 7); Ann wins the frame 60-50.');
  });
});

describe('verdictSentence: three-cushion', () => {
  it('a point says the run', () => {
    const g0 = newGame('threecushion', ['4', '5'], { seed: 1 });
    const events = [
      { t: 1, kind: 'ball', balls: ['white', 'red'] },
      ...[2, 3, 4].map((t) => ({ t, kind: 'cushion', balls: ['white'] })),
      { t: 5, kind: 'ball', balls: ['white', 'yellow'] },
    ];
    const g = applyShot(g0, { ...stroke('4'), ball: 'white' }, { balls: g0.balls.map((b) => ({ ...b, pocketed: false })), events });
    expect(verdictSentence(g, g.verdict!, names)).toBe('Point for Ann (run 1).');
  });
  it('a point with the run, and no point', () => {
    const g0 = newGame('threecushion', ['4', '5'], { seed: 1 });
    const cue = g0.turn === '4' ? 'white' : 'yellow';
    expect(g0.turn).toBe('4');
    const miss = applyShot(g0, { ...stroke('4'), ball: cue }, { balls: g0.balls.map((b) => ({ ...b, pocketed: false })), events: [{ t: 1, kind: 'ball', balls: [cue, 'red'] }] });
    expect(verdictSentence(miss, miss.verdict!, names)).toBe('No point for Ann; Bob to play.');
  });
});

describe('verdictSentence: the end of a game', () => {
  it('a concession and a claim', () => {
    const c = concede(nine(), '4');
    expect(verdictSentence(c, c.verdict!, names)).toBe('Ann concedes; Bob wins.');
    const claimed = claimGame(nine(), '5');
    expect(verdictSentence(claimed, claimed.verdict!, names, { action: 'claim' })).toBe('Bob claims the game: Ann has left; Bob wins.');
  });
});
