// Snooker, by the WPBSA Official Rules of Snooker (Section 2, Definitions; Section 3, The Game).
// Rules are cited by section and name: "S3 Spotting Colours" is the rule of that name in Section 3.
import type { TableSpec } from '../physics/tables.ts';
import { addFoul, describeList, opponent, putInHand, specOfGame } from './common.ts';
import { RuleError } from './errors.ts';
import { snookerMarks } from './marks.ts';
import type { ShotFacts } from './outcome.ts';
import { freeAlongX, overlapping } from './placement.ts';
import { POOL_CUE, SNOOKER_COLOURS, SNOOKER_VALUES } from './racks.ts';
import { nextInt } from './rng.ts';
import { isSnookered } from './snookered.ts';
import type { Ball, PlayerId, Shot, SnookerColour, SnookerGame, SnookerOn, Verdict } from './types.ts';

export function isRed(id: string): boolean {
  return id.startsWith('red');
}

export function isColour(id: string): id is SnookerColour {
  return (SNOOKER_COLOURS as readonly string[]).includes(id);
}

/** Points of a ball (S3 Description of the game: red 1, yellow 2 ... black 7). */
export function ballValue(id: string): number {
  return isColour(id) ? SNOOKER_VALUES[id] : isRed(id) ? 1 : 0;
}

/** The balls on for state `on` among `balls`. */
export function ballsOnFor(on: SnookerOn, balls: readonly Ball[]): Ball[] {
  if (on === 'red') return balls.filter((b) => isRed(b.id));
  if (on === 'colour') return balls.filter((b) => isColour(b.id));
  return balls.filter((b) => b.id === on);
}

/** The balls the striker may legally meet first, free ball included. */
export function snookerTargets(g: SnookerGame): string[] {
  const on = ballsOnFor(g.on, g.balls).map((b) => b.id);
  if (!g.freeBall) return on;
  return g.balls.filter((b) => b.id !== POOL_CUE).map((b) => b.id);
}

function nextColour(c: SnookerColour): SnookerColour | null {
  const i = SNOOKER_COLOURS.indexOf(c);
  return (SNOOKER_COLOURS[i + 1] as SnookerColour | undefined) ?? null;
}

export function checkSnookerShot(g: SnookerGame, shot: Shot): void {
  const n = shot.nominated;
  if (n === undefined) return;
  if (!g.balls.some((b) => b.id === n) || n === POOL_CUE) {
    throw new RuleError('bad-declaration', `the nominated ball "${n}" is not an object ball on the table`);
  }
  if (g.freeBall) {
    // S3 Snookered after a Foul / S2 Free Ball: any ball other than the ball on.
    const on = ballsOnFor(g.on, g.balls).map((b) => b.id);
    if (on.includes(n)) throw new RuleError('bad-declaration', `a free ball must be a ball other than the ball on; "${n}" is on`);
    return;
  }
  if (g.on === 'colour') {
    // S3 Mode of Play: after a red, the striker nominates the colour he plays.
    if (!isColour(n)) throw new RuleError('bad-declaration', `after a red the nominated ball must be a colour, not "${n}"`);
    return;
  }
  throw new RuleError(
    'bad-declaration',
    'a nominated ball applies only to a free ball (snookered after a foul) or to the colour after a red',
  );
}

export function judgeSnooker(g: SnookerGame, shot: Shot, f: ShotFacts, v: Verdict): void {
  const spec = specOfGame(g);
  const R = spec.ballRadius;
  const shooter = shot.player;
  const other = opponent(g, shooter);
  const on = g.on;
  const before = g.balls;
  const free = g.freeBall && shot.nominated !== undefined ? shot.nominated : null;
  const objectsBefore = before.filter((b) => b.id !== POOL_CUE).map((b) => b.id);
  const onBefore = ballsOnFor(on, before).map((b) => b.id);
  const isOn = (id: string): boolean => onBefore.includes(id);
  const first = f.firstHit;
  const cuePotted = f.pots.some((p) => p.id === POOL_CUE);
  const potted = f.pots.filter((p) => p.id !== POOL_CUE).map((p) => p.id);
  const involved: number[] = [];

  // The colour played after a red: nominated, or else deemed to be the colour met first.
  let colour: SnookerColour | null = null;
  if (on === 'colour') {
    if (shot.nominated !== undefined && isColour(shot.nominated)) colour = shot.nominated;
    else if (first.length === 1 && isColour(first[0] as string)) colour = first[0] as SnookerColour;
  }
  const onValue = on === 'red' ? 1 : on === 'colour' ? (colour ? SNOOKER_VALUES[colour] : 0) : SNOOKER_VALUES[on];

  // First contact (S3 Fouls: failing to hit any ball; first hitting a ball not on; hitting
  // simultaneously two balls other than two reds or a free ball and the ball on: S3 Simultaneous Hit).
  if (first.length === 0) {
    addFoul(v, 'no-contact');
  } else if (free !== null) {
    // S3 Snookered after a Foul (b)(i): the nominated ball must be hit first, or simultaneously
    // with the ball on.
    const ok = first.includes(free) && first.every((id) => id === free || isOn(id));
    if (!ok) {
      addFoul(v, 'wrong-ball-first');
      for (const id of first) if (id !== free && !isOn(id)) involved.push(ballValue(id));
    }
  } else {
    const ok =
      on === 'red' ? first.every((id) => isRed(id)) :
      on === 'colour' ? first.length === 1 && colour !== null && first[0] === colour :
      first.length === 1 && first[0] === on;
    if (!ok) {
      addFoul(v, 'wrong-ball-first');
      for (const id of first) if (!(on === 'red' && isRed(id))) involved.push(ballValue(id));
    }
  }

  // Pots (S3 Fouls: causing a ball not on to enter a pocket; the cue ball to enter a pocket).
  const allowed = new Set<string>(on === 'colour' ? (colour ? [colour] : []) : onBefore);
  if (free !== null) allowed.add(free);
  for (const id of potted) {
    if (!allowed.has(id)) {
      addFoul(v, 'pot-not-on');
      involved.push(ballValue(id));
    }
  }
  if (cuePotted) addFoul(v, 'in-off');

  g.balls = f.remaining;
  g.shots += 1;
  g.choices = [];
  g.ballInHand = false;
  g.offender = null;
  const redsLeft = (): number => g.balls.filter((b) => isRed(b.id)).length;
  const pottedReds = potted.filter(isRed);

  if (!v.foul && free !== null && potted.length === 0) {
    // S3 Snookered after a Foul (b)(ii): it is a foul to leave the opponent snookered by the free
    // ball on all reds or the ball on, except when only pink and black remain.
    const pinkBlackOnly = objectsBefore.every((id) => id === 'pink' || id === 'black');
    const cue = g.balls.find((b) => b.id === POOL_CUE);
    const fb = g.balls.find((b) => b.id === free);
    const nextOn = ballsOnFor(on === 'colour' ? 'red' : on, g.balls);
    if (!pinkBlackOnly && cue && fb && isSnookered(cue, nextOn, [fb], R)) addFoul(v, 'free-ball-snooker');
  }

  if (v.foul) {
    // S3 Penalties: the value of the ball on, or the higher value of the balls involved, at least 4.
    const penalty = Math.max(4, onValue, ...involved);
    g.scores[other] = (g.scores[other] ?? 0) + penalty;
    v.points[other] = penalty;
    v.potted = pottedReds; // reds are never replaced (S3 Spotting Colours applies to colours only)
    respot(g, spec, potted.filter(isColour), v);
    g.break = 0;
    g.turn = other;
    v.next = other;
    const onlyBlack = on === 'black';
    g.on = redsLeft() > 0 ? 'red' : on === 'red' || on === 'colour' ? 'yellow' : on;
    v.message = `foul by ${shooter} (${v.fouls.join(', ')}): ${penalty} to ${other}`;
    if (onlyBlack) {
      // S2 Frame (c) and S3 End of Frame: when only the black remains, a foul ends the frame.
      endFrame(g, spec, v);
      return;
    }
    g.offender = shooter;
    g.choices = ['pass']; // S3 Action after a Foul: the next player may have the offender play again
    if (cuePotted) {
      g.balls = putInHand(spec, g.balls, POOL_CUE, 'D');
      g.ballInHand = 'D';
    }
    g.freeBall = !cuePotted && snookeredNow(g, spec);
    if (g.freeBall) v.message += '; free ball';
    return;
  }

  // A fair stroke.
  g.freeBall = false;
  let points = 0;
  let scored = false;
  if (on === 'red') {
    // S3 Mode of Play: any number of reds count one each; a free ball taken as a red counts one
    // more and is spotted (S3 Snookered after a Foul (c)-(e)).
    points = pottedReds.length + (free !== null && potted.includes(free) ? 1 : 0);
    scored = points > 0;
    v.potted = pottedReds;
    respot(g, spec, potted.filter(isColour), v);
    g.on = scored ? 'colour' : redsLeft() > 0 ? 'red' : 'yellow';
  } else if (on === 'colour') {
    // The colour after a red is spotted, also after the last red; then reds again, or the yellow.
    scored = colour !== null && potted.includes(colour);
    points = scored && colour ? SNOOKER_VALUES[colour] : 0;
    respot(g, spec, potted.filter(isColour), v);
    g.on = redsLeft() > 0 ? 'red' : 'yellow';
  } else {
    // The end sequence, yellow to black, each potted in turn staying down.
    if (potted.includes(on)) {
      scored = true;
      points = SNOOKER_VALUES[on];
      v.potted = [on];
      respot(g, spec, potted.filter((id) => id !== on && isColour(id)), v);
      g.on = nextColour(on) ?? on;
    } else if (free !== null && potted.includes(free)) {
      scored = true;
      points = SNOOKER_VALUES[on]; // the free ball takes the value of the ball on, and is spotted
      respot(g, spec, [free], v);
    }
  }
  g.scores[shooter] = (g.scores[shooter] ?? 0) + points;
  v.points[shooter] = points;
  if (scored) {
    g.break += points;
    v.continues = true;
    v.next = shooter;
    v.message = `${shooter} pots ${describeList(potted)} for ${points} (break ${g.break})`;
  } else {
    g.break = 0;
    g.turn = other;
    v.next = other;
    v.message = `${shooter} scores nothing; ${other} to play`;
  }
  if (on === 'black' && scored) {
    endFrame(g, spec, v);
    return;
  }
}

/** Whether the striker on turn is snookered on the balls on (see snookered.ts). */
export function snookeredNow(g: SnookerGame, spec: TableSpec): boolean {
  const cue = g.balls.find((b) => b.id === POOL_CUE);
  if (!cue) return false;
  const on = ballsOnFor(g.on, g.balls);
  const onIds = new Set(on.map((b) => b.id));
  const obstacles = g.balls.filter((b) => b.id !== POOL_CUE && !onIds.has(b.id));
  return isSnookered(cue, on, obstacles, spec.ballRadius);
}

/**
 * S3 Spotting Colours: a colour goes back on its own spot; if that is occupied (a ball placed there
 * would touch another), on the highest-value spot available; if all are occupied, as near as
 * possible to its own spot between it and the nearest part of the top cushion, and for pink and
 * black when that is full, as near as possible below its spot on the centre line. When several
 * colours are spotted, the higher value has precedence.
 */
function respot(g: SnookerGame, spec: TableSpec, colours: readonly string[], v: Verdict): void {
  if (colours.length === 0) return;
  const spots = snookerMarks(spec).spots;
  const order = colours.filter(isColour).sort((a, b) => SNOOKER_VALUES[b] - SNOOKER_VALUES[a]);
  const placed = g.balls.filter((b) => !(order as readonly string[]).includes(b.id));
  // "Occupied" (S2 Definitions): a ball cannot be placed there without touching another ball.
  const touchSpec = { ...spec, ballRadius: spec.ballRadius + 1e-9 };
  const clearAt = (p: { x: number; y: number }): boolean => overlapping(touchSpec, placed, p) === null;
  const deferred: SnookerColour[] = [];
  for (const c of order) {
    if (clearAt(spots[c])) placed.push({ id: c, ...spots[c] });
    else deferred.push(c);
  }
  const byValue = [...SNOOKER_COLOURS].reverse();
  for (const c of deferred) {
    const spot = byValue.find((s) => clearAt(spots[s]));
    if (spot) {
      placed.push({ id: c, ...spots[spot] });
      continue;
    }
    const own = spots[c];
    const edge = spec.length / 2 - spec.ballRadius;
    const up = freeAlongX(spec, placed, own.y, own.x, 1, edge, true);
    const x = up ?? freeAlongX(spec, placed, own.y, own.x, -1, -edge, true);
    placed.push({ id: c, x: x ?? own.x, y: own.y });
  }
  g.balls = placed;
  for (const c of order) v.spotted.push(c);
}

/** The frame ends: the higher score wins; on a tie the black is re-spotted (S3 End of Frame). */
function endFrame(g: SnookerGame, spec: TableSpec, v: Verdict): void {
  const [a, b] = g.players as [PlayerId, PlayerId];
  const sa = g.scores[a] ?? 0;
  const sb = g.scores[b] ?? 0;
  if (sa !== sb) {
    const w = sa > sb ? a : b;
    g.winner = w;
    g.choices = [];
    g.freeBall = false;
    g.offender = null;
    v.rackWinner = w;
    v.next = w;
    v.continues = false;
    v.message += `; ${w} wins the frame ${Math.max(sa, sb)}-${Math.min(sa, sb)}`;
    return;
  }
  // Tie: the black is spotted, lots are drawn for the choice of who plays first, and that player
  // plays from in-hand; the next score or foul ends the frame.
  const lot = nextInt(g.rng, 2);
  g.rng = lot.state;
  const chooser = g.players[lot.value] as PlayerId;
  const m = snookerMarks(spec);
  const rest = g.balls.filter((x) => x.id !== 'black' && x.id !== POOL_CUE);
  g.balls = putInHand(spec, [...rest, { id: 'black', ...m.spots.black }], POOL_CUE, 'D');
  g.ballInHand = 'D';
  g.on = 'black';
  g.respottedBlack = true;
  g.freeBall = false;
  g.offender = null;
  g.break = 0;
  g.turn = chooser;
  g.choices = ['pass'];
  v.next = chooser;
  v.continues = chooser === v.player;
  v.spotted.push('black');
  v.message += `; scores level at ${sa}: the black is re-spotted, ${chooser} wins the lot and plays from hand or passes`;
}
