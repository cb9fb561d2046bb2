// Racks and opening positions. Random orders come from the seeded generator (rng.ts); the state
// after the draw is returned so that it goes back into the Game.
import type { TableSpec } from '../physics/tables.ts';
import { caromMarks, poolMarks, snookerMarks } from './marks.ts';
import { preferredSpot } from './placement.ts';
import { nextInt, shuffle } from './rng.ts';
import type { Ball, SnookerColour } from './types.ts';

export const POOL_CUE = 'cue';
export const POOL_OBJECT_BALLS = ['1', '2', '3', '4', '5', '6', '7', '8', '9', '10', '11', '12', '13', '14', '15'] as const;
export const SNOOKER_REDS = Array.from({ length: 15 }, (_, i) => `red${i + 1}`);
export const SNOOKER_COLOURS: readonly SnookerColour[] = ['yellow', 'green', 'brown', 'blue', 'pink', 'black'];
export const SNOOKER_VALUES: Readonly<Record<SnookerColour, number>> = {
  yellow: 2,
  green: 3,
  brown: 4,
  blue: 5,
  pink: 6,
  black: 7,
};
export const CAROM_BALLS = ['white', 'yellow', 'red'] as const;

/**
 * Slots of a tight triangular pack whose apex sits at (apexX, 0) and which grows towards +x:
 * rows[i] balls in row i, rows a ball radius times sqrt(3) apart, balls in a row 2R apart, so
 * neighbours touch (frozen), as a rack leaves them.
 */
function packSlots(R: number, apexX: number, rows: readonly number[]): Array<{ x: number; y: number }> {
  const dx = R * Math.sqrt(3);
  const out: Array<{ x: number; y: number }> = [];
  rows.forEach((n, i) => {
    for (let k = 0; k < n; k++) out.push({ x: apexX + i * dx, y: (2 * k - (n - 1)) * R });
  });
  return out;
}

/**
 * Nine-ball (WPA 2.2 Nine Ball Rack): a diamond, the 1 at the apex on the foot spot, the 9 in the
 * middle, the others without pattern (here: drawn from the generator).
 */
export function nineBallRack(spec: TableSpec, rng: number): { balls: Ball[]; rng: number } {
  const slots = packSlots(spec.ballRadius, poolMarks(spec).footSpot.x, [1, 2, 3, 2, 1]);
  const middle = 4; // rows 1 + 2, then the middle of the row of three
  const drawn = shuffle(['2', '3', '4', '5', '6', '7', '8'], rng);
  const ids: string[] = [];
  let next = 0;
  for (let i = 0; i < slots.length; i++) ids.push(i === 0 ? '1' : i === middle ? '9' : (drawn.items[next++] as string));
  const balls = slots.map((s, i) => ({ id: ids[i] as string, x: s.x, y: s.y }));
  return { balls: [cueInKitchen(spec), ...balls], rng: drawn.state };
}

/**
 * Eight-ball (WPA 3.2 Eight Ball Rack): a triangle, the apex ball on the foot spot, the 8 in the
 * middle of the third row, one ball of each group on the two back corners, the others without
 * pattern (here: drawn from the generator).
 */
export function eightBallRack(spec: TableSpec, rng: number): { balls: Ball[]; rng: number } {
  const slots = packSlots(spec.ballRadius, poolMarks(spec).footSpot.x, [1, 2, 3, 4, 5]);
  const eightSlot = 4;
  const backLeft = 10;
  const backRight = 14;
  let s = rng;
  const solids = shuffle(['1', '2', '3', '4', '5', '6', '7'], s);
  s = solids.state;
  const stripes = shuffle(['9', '10', '11', '12', '13', '14', '15'], s);
  s = stripes.state;
  const side = nextInt(s, 2);
  s = side.state;
  const solidCorner = solids.items[0] as string;
  const stripeCorner = stripes.items[0] as string;
  const rest = shuffle([...solids.items.slice(1), ...stripes.items.slice(1)], s);
  s = rest.state;
  const ids: string[] = [];
  let next = 0;
  for (let i = 0; i < slots.length; i++) {
    if (i === eightSlot) ids.push('8');
    else if (i === backLeft) ids.push(side.value === 0 ? solidCorner : stripeCorner);
    else if (i === backRight) ids.push(side.value === 0 ? stripeCorner : solidCorner);
    else ids.push(rest.items[next++] as string);
  }
  const balls = slots.map((p, i) => ({ id: ids[i] as string, x: p.x, y: p.y }));
  return { balls: [cueInKitchen(spec), ...balls], rng: s };
}

function cueInKitchen(spec: TableSpec): Ball {
  return { id: POOL_CUE, ...preferredSpot(spec, 'kitchen') };
}

/** Gap left between the apex red and the pink ("as near as possible without touching"). */
export const RED_APEX_GAP = 0.001;

/**
 * Snooker (WPBSA Section 3 Rule 2, Position of Balls): the reds in a tight triangle whose apex red
 * stands as near to the pink as possible without touching it, its base parallel to and nearest the
 * top cushion; the colours on their spots (marks.ts); the cue ball in hand in the D.
 */
export function snookerSetup(spec: TableSpec): Ball[] {
  const m = snookerMarks(spec);
  const R = spec.ballRadius;
  const reds = packSlots(R, m.spots.pink.x + 2 * R + RED_APEX_GAP, [1, 2, 3, 4, 5]).map((p, i) => ({
    id: SNOOKER_REDS[i] as string,
    x: p.x,
    y: p.y,
  }));
  const colours = SNOOKER_COLOURS.map((c) => ({ id: c, x: m.spots[c].x, y: m.spots[c].y }));
  return [{ id: POOL_CUE, ...preferredSpot(spec, 'D') }, ...reds, ...colours];
}

/** Three-cushion opening position (marks.ts): white to break, yellow on the head spot, red on the top spot. */
export function caromSetup(spec: TableSpec): Ball[] {
  const m = caromMarks(spec);
  return [
    { id: 'white', ...m.breakSpot },
    { id: 'yellow', ...m.headSpot },
    { id: 'red', ...m.topSpot },
  ];
}
