// Public types of the cushion-impact kernel (Mathavan, Jackson and Parkin 2010).
// Frame (the paper's): x along the cushion, y perpendicular to it pointing into the cushion
// (vy > 0 approaches), z up, right-handed. SI units.

/** Ball velocity (m/s) and angular velocity (rad/s) in the cushion frame. */
export interface CushionState {
  readonly vx: number;
  readonly vy: number;
  readonly wx: number;
  readonly wy: number;
  readonly wz: number;
}

/** Physical constants of one impact. */
export interface CushionParams {
  /** Ball mass (kg), > 0. */
  readonly M: number;
  /** Ball radius (m), > 0. */
  readonly R: number;
  /** Height of the cushion nose above the cloth (m), in (R, 2R); sin θ = (h - R) / R. */
  readonly h: number;
  /** Cushion restitution e_e in [0, 1]: restitution work = e_e² × compression work. */
  readonly ee: number;
  /** Ball-table (sliding) friction μ_s >= 0. */
  readonly muS: number;
  /** Ball-cushion friction μ_w >= 0. */
  readonly muW: number;
}

/** Named accuracy settings: local error tolerances relative to the ball's speed (docs/cushion.md). */
export type CushionToleranceName = 'accurate' | 'balanced' | 'fast';

export interface CushionOptions {
  /** A named setting, or a number in [1e-12, 1e-2]: the per-step tolerance. Default 'accurate'. */
  readonly tolerance?: CushionToleranceName | number;
}

/**
 * How the impact ended: 'no-impact' (vy <= 0 on entry, the state returned unchanged);
 * 'restitution' (the restitution work reached e_e² times the compression work: the normal
 * case); 'stalled' (the ball stopped receding before that, vy back at 0 with the impulse pushing
 * it in or both contacts rolling: the state at that instant, with vy = 0).
 */
export type CushionOutcome = 'no-impact' | 'restitution' | 'stalled';

/** Tolerance of each named setting (relative local error per step). */
export const CUSHION_TOLERANCES: Readonly<Record<CushionToleranceName, number>> = {
  // The loosest tolerance whose error stays below 5e-6 V0 (half the goal) over the issue's
  // range with the paper's and each table's constants (docs/cushion.md, "Accuracy and cost").
  accurate: 1e-6,
  balanced: 1e-5,
  fast: 1e-4,
};
