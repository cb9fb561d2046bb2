// The cushion-impact cases of Mathavan, Jackson and Parkin (2010), "A theoretical analysis of
// billiard ball dynamics under cushion impacts", Proc. IMechE C 224(9) 1863-1873: the paper's
// constants, its way of stating an incoming ball, and the values it publishes (Figs. 9 and 12),
// defined once for the tests, the figures and the lab page.
import { sinCos } from '../physics/det-math.ts';
import type { CushionParams, CushionState } from '../physics/index.ts';

/** The paper's constants (snooker): M, R, h = 7R/5, e_e, μ_s (table), μ_w (cushion). */
export const PAPER: CushionParams = { M: 0.1406, R: 0.02625, h: 0.02625 * 1.4, ee: 0.98, muS: 0.212, muW: 0.14 };

/**
 * The paper's incoming ball: speed V0 at incidence α (degrees from the cushion line, 90 is
 * head-on), topspin ω_T = kT V0 / R about the horizontal axis across the path, sidespin
 * ω_S = kS V0 / R about z: v = (V0 cos α, V0 sin α, 0), ω = (-ω_T sin α, ω_T cos α, ω_S).
 */
export function paperState(V0: number, alphaDeg: number, kT: number, kS: number, R: number): CushionState {
  const { sin, cos } = sinCos((alphaDeg * Math.PI) / 180);
  const wT = (kT * V0) / R;
  return { vx: V0 * cos, vy: V0 * sin, wx: -wT * sin, wy: wT * cos, wz: (kS * V0) / R };
}

/** A rebound the paper publishes, with the accuracy its figures carry. */
export interface PublishedRebound {
  readonly label: string;
  readonly figure: 9 | 12;
  readonly V0: number;
  readonly alpha: number;
  readonly kT: number;
  readonly kS: number;
  /** Rebound speed (m/s) and angle from the cushion line (degrees). */
  readonly speed: number;
  readonly angle: number;
  readonly speedTol: number;
  readonly angleTol: number;
}

const natural = (alpha: number, speed: number, angle: number): PublishedRebound =>
  ({ label: `natural roll, ${alpha}°`, figure: 9, V0: 1, alpha, kT: 1, kS: 0, speed, angle, speedTol: 1e-3, angleTol: 0.05 });

/** The published rebounds: natural roll at 15-75° and no spin at 45° (Fig. 9), the Fig. 12 case. */
export const PUBLISHED: readonly PublishedRebound[] = [
  natural(15, 0.9175, 15.913),
  natural(30, 0.8614, 34.001),
  natural(45, 0.8476, 52.678),
  natural(60, 0.8672, 68.824),
  natural(75, 0.8976, 80.03),
  { label: 'no spin, 45°', figure: 9, V0: 1, alpha: 45, kT: 0, kS: 0, speed: 0.7564, angle: 56.22, speedTol: 1e-3, angleTol: 0.05 },
  { label: 'Fig. 12 case', figure: 12, V0: 2, alpha: 45, kT: 1.5, kS: 2, speed: 2.2179, angle: 38.017, speedTol: 2e-3, angleTol: 0.05 },
];
