// The paper's Figs. 9, 10 and 12 (Mathavan, Jackson and Parkin 2010) computed by the kernel
// (shared/physics), paper constants.
import { cushionRebound } from '../shared/physics/index.ts';
import { cushionTrace } from '../shared/physics/diagnostics.ts';
import { PAPER, paperState } from '../tests/support/cushion-cases.ts';
import { figureSvg, PALETTE } from './figures-svg.ts';
import type { Series } from './figures-svg.ts';

const DEG = 180 / Math.PI;
const ALPHAS = Array.from({ length: 179 }, (_, i) => 0.5 + i * 0.5);
const CONSTANTS = `M = ${PAPER.M} kg, R = ${PAPER.R} m, h = 7R/5, e_e = ${PAPER.ee}, μ_s = ${PAPER.muS}, μ_w = ${PAPER.muW}`;

function reboundSeries(kT: number, kS: number, name: string, color: string): { speed: Series; angle: Series } {
  const speed: [number, number][] = [];
  const angle: [number, number][] = [];
  for (const a of ALPHAS) {
    const out = cushionRebound(paperState(1, a, kT, kS, PAPER.R), PAPER);
    speed.push([a, Math.hypot(out.vx, out.vy)]);
    angle.push([a, Math.atan2(-out.vy, out.vx) * DEG]);
  }
  return { speed: { name, points: speed, color }, angle: { name, points: angle, color } };
}

function reboundFigure(title: string, caption: string, lines: { speed: Series; angle: Series }[], angleMax = 90, speedRange: [number, number] = [0.55, 1.15]): string {
  return figureSvg(title, caption, [
    { title: 'Rebound speed', xLabel: 'incidence α (°)', yLabel: 'rebound speed (m/s)', series: lines.map((l) => l.speed), x: [0, 90], y: speedRange, legend: 'bl' },
    { title: 'Rebound angle', xLabel: 'incidence α (°)', yLabel: 'rebound angle β (°, from the cushion)', series: lines.map((l) => l.angle), x: [0, 90], y: [0, angleMax], legend: 'tl' },
  ]);
}

export function fig9(): string {
  const lines = [-1, 0, 1, 2].map((k, i) => reboundSeries(k, 0, `topspin k = ${k}`, PALETTE[i]!));
  return reboundFigure(
    'Fig. 9: rebound against incidence, topspin ω_T = k V0 / R, no sidespin, V0 = 1 m/s',
    CONSTANTS,
    lines,
  );
}

export function fig10(): string {
  const lines = [-2, -1, 0, 1, 2].map((k, i) => reboundSeries(1, k, `sidespin k = ${k}`, PALETTE[i]!));
  return reboundFigure(
    'Fig. 10: rebound of a rolling ball (k_T = 1) with sidespin ω_S = k V0 / R, V0 = 1 m/s',
    `${CONSTANTS}; angles above 90° rebound backwards along the cushion`,
    lines,
    120,
  );
}

export function fig12(): string {
  const V0 = 2;
  const t = cushionTrace(paperState(V0, 45, 1.5, 2, PAPER.R), PAPER);
  const slipI = t.trace.map((p) => [p.P, Math.hypot(p.xI, p.yI)] as const);
  const slipC = t.trace.map((p) => [p.P, Math.hypot(p.xC, p.yC)] as const);
  // Directions in [0°, 360°), only where the slip is not negligible.
  const dir = (x: number, y: number): number => ((Math.atan2(y, x) * DEG) % 360 + 360) % 360;
  const phiI = t.trace.filter((p) => Math.hypot(p.xI, p.yI) > 1e-6).map((p) => [p.P, dir(p.xI, p.yI)] as const);
  const phiC = t.trace.filter((p) => Math.hypot(p.xC, p.yC) > 1e-6).map((p) => [p.P, dir(p.xC, p.yC)] as const);
  const vy = t.trace.map((p) => [p.P, p.vy] as const);
  const out = t.state;
  return figureSvg(
    'Fig. 12: slip against impulse, V0 = 2 m/s, α = 45°, ω_S = 2 V0/R, ω_T = 1.5 V0/R',
    `${CONSTANTS}; rebound ${Math.hypot(out.vx, out.vy).toFixed(4)} m/s at ${(Math.atan2(-out.vy, out.vx) * DEG).toFixed(3)}°`,
    [
      {
        title: 'Slip speeds',
        xLabel: 'impulse P at the cushion (N s)',
        yLabel: 'slip speed (m/s)',
        series: [
          { name: 's at I (cushion)', points: slipI, color: PALETTE[0] },
          { name: "s' at C (table)", points: slipC, color: PALETTE[1] },
          { name: 'v_y of the centre', points: vy, color: PALETTE[2], dash: '5 3' },
        ],
      },
      {
        title: 'Slip directions',
        xLabel: 'impulse P at the cushion (N s)',
        yLabel: 'slip direction (°, from the cushion line)',
        series: [
          { name: 'φ at I (cushion)', points: phiI, color: PALETTE[0] },
          { name: "φ' at C (table)", points: phiC, color: PALETTE[1] },
        ],
        y: [0, 360],
      },
    ],
  );
}
