// The simulation's public data: what goes in (a scene and a shot) and what comes out (an outcome).
// Plain serialisable objects, the same on the server and in the browser.
import type { Motion } from './ball-state.ts';
import type { CushionParams, CushionToleranceName } from './cushion/index.ts';
import type { TableName } from './tables.ts';

export interface SceneBall {
  readonly id: string;
  /** Metres from the table centre, x along the length. */
  readonly x: number;
  readonly y: number;
}

/** Balls at rest on a table. */
export interface Scene {
  readonly table: TableName | string;
  readonly balls: readonly SceneBall[];
}

export interface Shot {
  /** Id of the struck ball. */
  readonly ball: string;
  /** Direction of travel, radians from +x, counter-clockwise. */
  readonly heading: number;
  /** Speed of the ball just after the strike (m/s). */
  readonly speed: number;
  /** Horizontal tip offset, fraction of R, + right. */
  readonly side: number;
  /** Vertical tip offset, fraction of R, + above centre. */
  readonly top: number;
}

export interface SimOptions {
  /** Bracket width of event times (s). Default 1e-12: positions to 1e-11 m at 10 m/s. */
  readonly rootTolerance?: number;
  /** Accuracy setting of the cushion impacts (see cushionRebound). Default 'accurate', the kernel's own. */
  readonly cushionTolerance?: CushionToleranceName | number;
  /**
   * Physical constants of the cushion impacts for this call (the physics lab): each field given
   * replaces the table's own (cushionParamsOf) in the cushion kernel only; the others keep the
   * table's. They change the cushion impacts only, not the ball's geometry (contacts, pockets) or
   * its motion on the cloth: a different R or muS here is the kernel's, not the table's. A field
   * set to undefined counts as not given. Default: the table's constants, bit for bit.
   */
  readonly cushion?: Partial<CushionParams>;
}

export type EventKind = 'ball' | 'cushion' | 'pocket' | 'motion';

export interface SimEvent {
  /** Time since the strike (s). */
  readonly t: number;
  readonly kind: EventKind;
  /** The balls involved: [a, b] for 'ball', [a] for the others. */
  readonly balls: readonly string[];
  /** 'cushion': which cushion (a rail, or a pocket's jaw nose or face). */
  readonly cushion?: string;
  /** 'pocket': which pocket. */
  readonly pocket?: string;
  /** 'ball' and 'cushion': the approach speed along the contact normal (m/s). */
  readonly speed?: number;
  /** 'motion': the motion left and the motion entered. */
  readonly from?: Motion;
  readonly to?: Motion;
}

export interface FinalBall {
  readonly id: string;
  readonly x: number;
  readonly y: number;
  readonly pocketed: boolean;
  readonly pocket?: string;
}

/** One piece of a ball's path: from t0 the closed form of its motion (cloth-motion.ts). */
export interface PathSegment {
  readonly t0: number;
  readonly motion: Motion;
  readonly x: number;
  readonly y: number;
  readonly vx: number;
  readonly vy: number;
  readonly wx: number;
  readonly wy: number;
  readonly wz: number;
  readonly ax: number;
  readonly ay: number;
}

export interface Outcome {
  readonly table: TableName;
  readonly balls: readonly FinalBall[];
  readonly events: readonly SimEvent[];
  /** Time until every ball rests or has dropped (s). */
  readonly duration: number;
  /** FNV-1a 64 of the final state (hash.ts), hex. */
  readonly hash: string;
  /** Every ball's path, in scene order, for sampling at any time (trajectory.ts). */
  readonly paths: readonly { readonly id: string; readonly segments: readonly PathSegment[] }[];
}
