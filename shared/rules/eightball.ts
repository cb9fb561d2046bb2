// Eight-ball, by the WPA World Standardized Rules (section 3, Eight Ball, with the general rules of
// section 1 and the fouls of section 6). Simplification: only the 8 must be called (pocket, and
// optionally ball); for the group balls the referee does not ask for calls (see 3.4 below).
import { addFoul, describeList, opponent, specOfGame } from './common.ts';
import { RuleError } from './errors.ts';
import type { ShotFacts } from './outcome.ts';
import { poolMarks } from './marks.ts';
import { spotPoolBall } from './placement.ts';
import { endRack, giveBallInHand } from './pool.ts';
import { POOL_CUE } from './racks.ts';
import type { EightBallGame, Group, PlayerId, Shot, Verdict } from './types.ts';

export function groupOf(id: string): Group | null {
  const n = Number(id);
  if (n >= 1 && n <= 7) return 'solids';
  if (n >= 9 && n <= 15) return 'stripes';
  return null;
}

function groupLeft(g: EightBallGame, group: Group): string[] {
  return g.balls.filter((b) => groupOf(b.id) === group).map((b) => b.id);
}

/** The balls the shooter may legally meet first. */
export function eightBallTargets(g: EightBallGame, player: PlayerId = g.turn): string[] {
  const objects = g.balls.filter((b) => b.id !== POOL_CUE).map((b) => b.id);
  if (g.phase === 'break') return objects; // WPA 3.3 (b): no particular ball first on the break
  if (g.groups === null) return objects.filter((id) => id !== '8'); // WPA 3.4: open table, not the 8
  const own = groupLeft(g, g.groups[player] as Group);
  return own.length > 0 ? own : objects.filter((id) => id === '8');
}

/** Whether the 8 is the shooter's legal object ball (his group is off the table). */
export function onTheEight(g: EightBallGame, player: PlayerId = g.turn): boolean {
  return g.phase === 'play' && g.groups !== null && groupLeft(g, g.groups[player] as Group).length === 0;
}

export function checkEightBallShot(g: EightBallGame, shot: Shot): void {
  const declares = shot.calledPocket !== undefined || shot.calledBall !== undefined;
  if (!declares) return;
  if (!onTheEight(g, shot.player)) {
    throw new RuleError(
      'bad-declaration',
      'a called pocket applies only when the 8 is the shooter\'s legal object ball (WPA 3: the 8 is called once the group is off the table)',
    );
  }
  if (shot.calledBall !== undefined && shot.calledBall !== '8') {
    throw new RuleError('bad-declaration', `the called ball can only be the 8 here, not "${shot.calledBall}"`);
  }
  if (shot.calledPocket === undefined) throw new RuleError('bad-declaration', 'calling the 8 needs a called pocket');
}

export function judgeEightBall(g: EightBallGame, shot: Shot, f: ShotFacts, v: Verdict): void {
  const shooter = shot.player;
  const other = opponent(g, shooter);
  const phase = g.phase;
  const targets = eightBallTargets(g, shooter);
  const eightWasOn = onTheEight(g, shooter);
  const kitchenInHand = g.ballInHand === 'kitchen';
  const before = g.balls;
  const cuePotted = f.pots.some((p) => p.id === POOL_CUE);
  const objectPots = f.pots.filter((p) => p.id !== POOL_CUE);
  const eightPot = objectPots.find((p) => p.id === '8');
  g.balls = f.remaining;
  g.shots += 1;
  g.choices = [];
  g.ballInHand = false;
  v.potted = objectPots.map((p) => p.id).filter((id) => id !== '8');

  if (cuePotted) addFoul(v, 'scratch'); // WPA 6.1
  if (f.firstHit.length === 0) {
    addFoul(v, 'no-contact'); // WPA 6.3: the cue ball must contact an object ball
  } else if (!f.firstHit.some((id) => targets.includes(id))) {
    addFoul(v, 'wrong-ball-first'); // WPA 6.2 (simultaneous contacts: the doubt goes to the shooter)
  } else if (phase === 'play' && objectPots.length === 0 && !f.cushionAfterContact) {
    addFoul(v, 'no-rail'); // WPA 6.3
  }
  if (phase === 'play' && kitchenInHand && f.firstHit.length > 0 && !cushionBeforeFirstHit(f, shot.ball)) {
    // WPA 1.5 Cue Ball in Hand (behind the head string): the cue ball must cross the head string
    // before it meets a ball. The events carry no positions, so we judge by the position before
    // the shot: meeting first a ball that lay behind the head string, with no cushion on the way,
    // is a foul.
    const headX = poolMarks(specOfGame(g)).headStringX;
    const first = before.find((b) => b.id === f.firstHit[0]);
    if (first && first.x < headX) addFoul(v, 'kitchen-not-crossed');
  }

  if (phase === 'break') {
    judgeBreak(g, shooter, other, f, v, eightPot !== undefined);
    return;
  }

  if (eightPot) {
    // WPA 3.8 Losing the Rack: (a) fouling when pocketing the 8, (b) pocketing the 8 when it is not
    // the legal object ball (also with the last ball of the group), (c) pocketing the 8 in a pocket
    // other than the called one.
    if (!eightWasOn) v.loss = 'eight-early';
    else if (v.foul) v.loss = 'eight-with-foul';
    else if (shot.calledPocket === undefined || eightPot.pocket !== shot.calledPocket) v.loss = 'eight-wrong-pocket';
    if (v.loss) {
      const why =
        v.loss === 'eight-early' ? 'before clearing the group' :
        v.loss === 'eight-with-foul' ? `with a foul (${v.fouls.join(', ')})` :
        shot.calledPocket === undefined ? 'without calling a pocket' :
        `in ${eightPot.pocket ?? 'an unknown pocket'}, not the called ${shot.calledPocket}`;
      v.message = `${shooter} pockets the 8 ${why} and loses the rack`;
      endRack(g, other, v);
    } else {
      v.message = `${shooter} pockets the 8 in the called ${shot.calledPocket} and wins the rack`;
      endRack(g, shooter, v);
    }
    return;
  }

  if (v.foul) {
    // WPA eight-ball standard fouls: ball in hand anywhere (1.5); balls pocketed on a foul stay down.
    giveBallInHand(g, shooter, 'anywhere');
    v.next = g.turn;
    v.message = `foul by ${shooter} (${v.fouls.join(', ')}): ${other} has ball in hand`;
    return;
  }

  if (g.groups === null && objectPots.length > 0) {
    // WPA 3.4: the group is chosen by legally pocketing a ball after the break. Without calls we
    // take the first ball met if it went down, else the first ball to go down.
    const pottedIds = objectPots.map((p) => p.id);
    const decider = pottedIds.find((id) => f.firstHit.includes(id)) ?? (pottedIds[0] as string);
    const group = groupOf(decider) as Group;
    g.groups = { [shooter]: group, [other]: group === 'solids' ? 'stripes' : 'solids' } as Record<PlayerId, Group>;
    v.continues = true;
    v.next = shooter;
    v.message = `${shooter} pockets ${describeList(pottedIds)} and takes the ${group}`;
    return;
  }
  const own = g.groups ? objectPots.filter((p) => groupOf(p.id) === g.groups?.[shooter]) : [];
  if (own.length > 0) {
    v.continues = true; // WPA eight-ball, continuing play: own group ball pocketed
    v.next = shooter;
    v.message = `${shooter} pockets ${describeList(objectPots.map((p) => p.id))} and continues`;
  } else {
    g.turn = other;
    v.next = other;
    v.message = objectPots.length > 0
      ? `${shooter} pockets only ${describeList(objectPots.map((p) => p.id))} (not his group); ${other} to play`
      : `${shooter} misses; ${other} to play`;
  }
}

function cushionBeforeFirstHit(f: ShotFacts, cue: string): boolean {
  return f.events.some((e) => e.kind === 'cushion' && e.balls.includes(cue) && f.firstHitT !== null && e.t < f.firstHitT);
}

/** WPA 3.3 Break Shot. */
function judgeBreak(g: EightBallGame, shooter: PlayerId, other: PlayerId, f: ShotFacts, v: Verdict, eightPotted: boolean): void {
  const spec = specOfGame(g);
  const objectPots = f.pots.filter((p) => p.id !== POOL_CUE);
  const scratch = v.fouls.includes('scratch');
  g.phase = 'play';
  g.groups = null; // 3.3 (c): the table stays open after the break
  if (eightPotted) {
    // 3.3 (e): the breaker may have the 8 spotted and go on, or re-break; (f) after a scratch the
    // opponent may have it spotted and shoot with ball in hand behind the head string, or re-break.
    // Spotting is the default; the other option is the choice 'rerack'.
    g.balls = [...g.balls, spotPoolBall(spec, scratch ? g.balls.filter((b) => b.id !== POOL_CUE) : g.balls, '8')];
    v.spotted.push('8');
    if (scratch) {
      giveBallInHand(g, shooter, 'kitchen');
      v.next = other;
      v.message = `${shooter} pockets the 8 on the break and scratches: the 8 is spotted, ${other} has ball in hand in the kitchen or may re-rack`;
    } else {
      v.continues = true;
      v.next = shooter;
      v.message = `${shooter} pockets the 8 on the break: it is spotted and ${shooter} continues, or may re-break`;
    }
    g.choices = ['rerack'];
    return;
  }
  const legal = objectPots.length > 0 || f.ballsToCushion.size >= 4;
  if (!legal) {
    // 3.3 (d): illegal break; the incoming player accepts the table as it lies (by shooting), or
    // re-racks and breaks, or has the offender break again.
    addFoul(v, 'illegal-break');
    if (scratch) giveBallInHand(g, shooter, 'kitchen');
    else g.turn = other;
    g.choices = ['rerack', 'rerack-other'];
    v.next = other;
    v.message = `illegal break by ${shooter}: ${other} may play on, re-rack and break, or have ${shooter} break again`;
    return;
  }
  if (v.foul) {
    // 3.3: a scratch on a legal break gives the incoming player ball in hand behind the head string.
    giveBallInHand(g, shooter, scratch ? 'kitchen' : 'anywhere');
    v.next = other;
    v.message = `foul on the break by ${shooter} (${v.fouls.join(', ')}): ${other} has ball in hand` + (scratch ? ' in the kitchen' : '');
    return;
  }
  if (objectPots.length > 0) {
    v.continues = true;
    v.next = shooter;
    v.message = `${shooter} breaks and pockets ${describeList(objectPots.map((p) => p.id))}; the table is open`;
  } else {
    g.turn = other;
    v.next = other;
    v.message = `legal break by ${shooter}, nothing down; ${other} to play on an open table`;
  }
}
