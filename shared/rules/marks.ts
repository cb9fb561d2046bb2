// Table markings the referees need, from the playing area of shared/physics (metres from the
// centre, x along the length; the bottom end x = -length/2 is the head end of a pool table and the
// baulk end of a snooker table, see pockets.ts).
import { tableSpec, type TableName, type TableSpec } from '../physics/tables.ts';
import type { Point } from './types.ts';

/** Pool (WPA Definitions): the head string, the foot and head spots, a quarter length from each end rail. */
export interface PoolMarks {
  headStringX: number;
  footSpot: Point;
  headSpot: Point;
}

export function poolMarks(spec: TableSpec): PoolMarks {
  const q = spec.length / 4;
  return { headStringX: -q, footSpot: { x: q, y: 0 }, headSpot: { x: -q, y: 0 } };
}

// WPBSA Official Rules of Snooker, Section 1 (The Table), Rules 1(d)-(f): the baulk line is drawn
// 737 mm (29 in) from the face of the bottom cushion; the D is a semicircle of radius 292 mm
// (11.5 in) centred on the middle of the baulk line, behind it; the spots (Rule 1(f)): brown at the
// middle of the baulk line, yellow at its right-hand and green at its left-hand intersection with
// the D as seen from the baulk end (right is -y, left is +y: see pockets.ts); blue on the centre
// spot; pink midway between the centre spot and the face of the top cushion; black 324 mm
// (12.75 in) from the face of the top cushion.
export const BAULK_FROM_BOTTOM = 0.737;
export const D_RADIUS = 0.292;
export const BLACK_FROM_TOP = 0.324;

export interface SnookerMarks {
  baulkX: number;
  dRadius: number;
  spots: Readonly<Record<'yellow' | 'green' | 'brown' | 'blue' | 'pink' | 'black', Point>>;
}

export function snookerMarks(spec: TableSpec): SnookerMarks {
  const half = spec.length / 2;
  const baulkX = -half + BAULK_FROM_BOTTOM;
  return {
    baulkX,
    dRadius: D_RADIUS,
    spots: {
      yellow: { x: baulkX, y: -D_RADIUS },
      green: { x: baulkX, y: D_RADIUS },
      brown: { x: baulkX, y: 0 },
      blue: { x: 0, y: 0 },
      pink: { x: half / 2, y: 0 },
      black: { x: half - BLACK_FROM_TOP, y: 0 },
    },
  };
}

// UMB carom billiards, three-cushion: the opening position. The red on the top (foot) spot, the
// opponent's ball (yellow) on the starting (head) spot, the breaker's ball on the head string
// 182 mm to the side of the head spot (we use the right side, -y). Spots lie on the long string a
// quarter of the length from each short cushion (the second diamond).
export const CAROM_BREAK_OFFSET = 0.182;

export interface CaromMarks {
  topSpot: Point;
  headSpot: Point;
  breakSpot: Point;
}

export function caromMarks(spec: TableSpec): CaromMarks {
  const q = spec.length / 4;
  return { topSpot: { x: q, y: 0 }, headSpot: { x: -q, y: 0 }, breakSpot: { x: -q, y: -CAROM_BREAK_OFFSET } };
}

export function specOf(table: TableName): TableSpec {
  return tableSpec(table);
}
