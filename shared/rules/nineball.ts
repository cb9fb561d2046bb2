// Nine-ball, by the WPA World Standardized Rules (section 2, Nine Ball, with the general rules of
// section 1 and the fouls of section 6).
import { addFoul, describeList, opponent, specOfGame } from './common.ts';
import { RuleError } from './errors.ts';
import type { ShotFacts } from './outcome.ts';
import { spotPoolBall } from './placement.ts';
import { endRack, giveBallInHand } from './pool.ts';
import { POOL_CUE } from './racks.ts';
import type { NineBallGame, Shot, Verdict } from './types.ts';

/** The lowest-numbered object ball on the table: the ball the cue ball must meet first (WPA 2, 6.2). */
export function lowestBall(g: NineBallGame): string | null {
  let best: number | null = null;
  for (const b of g.balls) {
    if (b.id === POOL_CUE) continue;
    const n = Number(b.id);
    if (best === null || n < best) best = n;
  }
  return best === null ? null : String(best);
}

export function checkNineBallShot(g: NineBallGame, shot: Shot): void {
  if (shot.pushOut && g.phase !== 'push-out') {
    throw new RuleError(
      'bad-declaration',
      g.phase === 'break'
        ? 'a push-out cannot be declared on the break (WPA 2.4)'
        : 'a push-out may only be declared on the shot right after a legal break (WPA 2.4)',
    );
  }
}

/** Judge one shot; g is the caller's private copy and is changed in place. */
export function judgeNineBall(g: NineBallGame, shot: Shot, f: ShotFacts, v: Verdict): void {
  const shooter = shot.player;
  const other = opponent(g, shooter);
  const lowest = lowestBall(g);
  const phase = g.phase;
  const pushOut = shot.pushOut === true;
  const cuePotted = f.pots.some((p) => p.id === POOL_CUE);
  const objectPots = f.pots.filter((p) => p.id !== POOL_CUE).map((p) => p.id);
  const ninePotted = objectPots.includes('9');
  g.balls = f.remaining;
  g.shots += 1;
  g.choices = [];
  g.ballInHand = false;

  // Fouls. WPA 6.1 cue ball scratch; on a push-out 6.2 and 6.3 are suspended (WPA 2.4).
  if (cuePotted) addFoul(v, 'scratch');
  if (!pushOut) {
    if (f.firstHit.length === 0) {
      addFoul(v, 'no-contact'); // WPA 6.3: the cue ball must contact an object ball
    } else if (lowest === null || !f.firstHit.includes(lowest)) {
      // WPA 6.2 Wrong Ball First. When the lowest ball and another are met at the same instant
      // the doubt goes to the shooter (the events cannot order them).
      addFoul(v, 'wrong-ball-first');
    } else if (phase === 'break') {
      // WPA 2.3 (b): if no ball is pocketed, at least four object balls must be driven to rails.
      if (objectPots.length === 0 && f.ballsToCushion.size < 4) addFoul(v, 'illegal-break');
    } else if (objectPots.length === 0 && !f.cushionAfterContact) {
      addFoul(v, 'no-rail'); // WPA 6.3 No Rail after Contact
    }
  }

  v.potted = objectPots.filter((id) => id !== '9' || (!v.foul && !pushOut));
  if (v.foul) {
    // WPA 2.6: the 9 pocketed on a foul is spotted; other balls stay down.
    if (ninePotted) respotNine(g, v);
    const count = (g.fouls[shooter] ?? 0) + 1;
    g.fouls[shooter] = count;
    g.phase = 'play'; // no push-out after a foul on the break (WPA 2.4)
    if (count >= 3) {
      // WPA 2.8 Serious Fouls / 6.14 Three Consecutive Fouls: the rack is lost.
      v.loss = 'three-fouls';
      v.message = `${shooter} fouls (${v.fouls.join(', ')}) for the third time in a row and loses the rack`;
      endRack(g, other, v);
      return;
    }
    // WPA 2.7 Standard Fouls and 1.5: the incoming player has cue ball in hand anywhere.
    giveBallInHand(g, shooter, 'anywhere');
    v.next = g.turn;
    v.message = `foul by ${shooter} (${v.fouls.join(', ')}): ${other} has ball in hand` +
      (v.spotted.length ? '; the 9 is spotted' : '') + (count === 2 ? `; ${shooter} is on two fouls` : '');
    return;
  }

  g.fouls[shooter] = 0;
  if (pushOut) {
    // WPA 2.4: after a legal push-out the other player chooses who shoots next; a pocketed 9 is
    // spotted (2.6), other balls stay down, and the pusher does not continue (2.5).
    if (ninePotted) respotNine(g, v);
    g.phase = 'play';
    g.turn = other;
    g.choices = ['pass'];
    v.next = other;
    v.message = `${shooter} pushes out (potted ${describeList(v.potted)}); ${other} may shoot or pass the shot back`;
    return;
  }
  if (ninePotted) {
    v.message = `${shooter} pockets the 9 and wins the rack`;
    endRack(g, shooter, v);
    return;
  }
  g.phase = phase === 'break' ? 'push-out' : 'play';
  if (objectPots.length > 0) {
    // WPA 2.5 Continuing Play.
    v.continues = true;
    v.next = shooter;
    v.message = `${shooter} pockets ${describeList(objectPots)} and continues`;
  } else {
    g.turn = other;
    v.next = other;
    v.message = phase === 'break' ? `legal break by ${shooter}, nothing down; ${other} to play` : `${shooter} misses; ${other} to play`;
  }
}

function respotNine(g: NineBallGame, v: Verdict): void {
  const spec = specOfGame(g);
  const others = g.balls.filter((b) => b.id !== POOL_CUE || v.fouls.length === 0);
  g.balls = [...g.balls, spotPoolBall(spec, others, '9')];
  v.spotted.push('9');
}
