// The paper's Figs. 9, 10 and 12 (Mathavan, Jackson and Parkin 2010) computed by the kernel for
// any constants, with the values the paper publishes drawn on them: the lab page draws these live
// and `npm run figures` writes them, with the paper's constants, to docs/figures.
import { cushionRebound } from '../../shared/physics/index.ts';
import type { CushionParams } from '../../shared/physics/index.ts';
import { cushionTrace } from '../../shared/physics/diagnostics.ts';
import { paperState, PUBLISHED } from '../../shared/scenes/index.ts';
import { figureSvg, PALETTE } from './svg-plot.ts';
import type { Mark, Series, Span } from './svg-plot.ts';

const DEG = 180 / Math.PI;
const ALPHAS = Array.from({ length: 90 }, (_, i) => 0.5 + i);

/** An incoming ball as the paper states it: V0 (m/s), incidence α (°), topspin and sidespin k. */
export interface IncomingBall {
  readonly V0: number;
  readonly alpha: number;
  readonly kT: number;
  readonly kS: number;
}

/** The Fig. 12 case: V0 = 2 m/s, α = 45°, ω_T = 1.5 V0/R, ω_S = 2 V0/R. */
export const FIG12_BALL: IncomingBall = { V0: 2, alpha: 45, kT: 1.5, kS: 2 };

export interface Rebound {
  readonly speed: number;
  /** Angle from the cushion line (°). */
  readonly angle: number;
  readonly wx: number;
  readonly wy: number;
  readonly wz: number;
}

export function rebound(params: CushionParams, b: IncomingBall): Rebound {
  const out = cushionRebound(paperState(b.V0, b.alpha, b.kT, b.kS, params.R), params);
  return { speed: Math.hypot(out.vx, out.vy), angle: Math.atan2(-out.vy, out.vx) * DEG, wx: out.wx, wy: out.wy, wz: out.wz };
}

const constants = (p: CushionParams): string =>
  `M = ${p.M} kg, R = ${p.R} m, h = ${(p.h / p.R).toFixed(3)} R, e_e = ${p.ee}, μs = ${p.muS}, μw = ${p.muW}`;

function reboundLines(params: CushionParams, kT: number, kS: number, name: string, color: string): { speed: Series; angle: Series } {
  const speed: [number, number][] = [];
  const angle: [number, number][] = [];
  for (const alpha of ALPHAS) {
    const r = rebound(params, { V0: 1, alpha, kT, kS });
    speed.push([alpha, r.speed]);
    angle.push([alpha, r.angle]);
  }
  return { speed: { name, points: speed, color }, angle: { name, points: angle, color } };
}

/** The paper's published rebounds at V0 = 1 m/s with the kernel's value beside each, as marks. */
function publishedMarks(params: CushionParams, kTs: readonly number[]): { speed: Mark[]; angle: Mark[] } {
  const speed: Mark[] = [];
  const angle: Mark[] = [];
  for (const p of PUBLISHED) {
    if (p.figure !== 9 || !kTs.includes(p.kT)) continue;
    const r = rebound(params, p);
    const color = PALETTE[kTs.indexOf(p.kT)] ?? '#000';
    const label = `published (${p.label}): ${p.speed} m/s at ${p.angle}°; kernel: ${r.speed.toFixed(4)} m/s at ${r.angle.toFixed(3)}°`;
    speed.push({ x: p.alpha, y: p.speed, color, label });
    angle.push({ x: p.alpha, y: p.angle, color, label });
  }
  return { speed, angle };
}

function reboundFigure(
  title: string, caption: string, lines: { speed: Series; angle: Series }[], marks: { speed: Mark[]; angle: Mark[] },
  angleMax: number,
): string {
  return figureSvg(title, caption, [
    { title: 'Rebound speed', xLabel: 'incidence α (°)', yLabel: 'rebound speed (m/s)', series: lines.map((l) => l.speed), x: [0, 90], marks: marks.speed },
    { title: 'Rebound angle', xLabel: 'incidence α (°)', yLabel: 'rebound angle β (°, from the cushion)', series: lines.map((l) => l.angle), x: [0, 90], y: [0, angleMax], marks: marks.angle },
  ]);
}

/** Fig. 9: rebound against incidence for topspins k = -1..2, no sidespin, V0 = 1 m/s. */
export function fig9(params: CushionParams): string {
  const kTs = [-1, 0, 1, 2];
  return reboundFigure(
    'Fig. 9: rebound against incidence, topspin ω_T = k V0 / R, no sidespin, V0 = 1 m/s',
    `${constants(params)}; circles: the paper's published values (hover for the numbers)`,
    kTs.map((k, i) => reboundLines(params, k, 0, `topspin k = ${k}`, PALETTE[i]!)),
    publishedMarks(params, kTs),
    90,
  );
}

/** Fig. 10: rebound of a rolling ball (k_T = 1) with sidespins k = -2..2, V0 = 1 m/s. */
export function fig10(params: CushionParams): string {
  const kSs = [-2, -1, 0, 1, 2];
  return reboundFigure(
    'Fig. 10: rebound of a rolling ball (k_T = 1) with sidespin ω_S = k V0 / R, V0 = 1 m/s',
    `${constants(params)}; angles above 90° rebound backwards along the cushion`,
    kSs.map((k, i) => reboundLines(params, 1, k, `sidespin k = ${k}`, PALETTE[i]!)),
    { speed: [], angle: [] },
    180,
  );
}

/** The impact's phases along the impulse: which contacts roll, and compression or restitution. */
export interface Phases {
  readonly contacts: readonly Span[];
  readonly halves: readonly Span[];
}

/** Fig. 12: slips, their directions and vy against the impulse, for any incoming ball. */
export function fig12(params: CushionParams, ball: IncomingBall): { svg: string; phases: Phases; rebound: Rebound } {
  const t = cushionTrace(paperState(ball.V0, ball.alpha, ball.kT, ball.kS, params.R), params);
  const pts = t.trace;
  const slipI = pts.map((p) => [p.P, Math.hypot(p.xI, p.yI)] as const);
  const slipC = pts.map((p) => [p.P, Math.hypot(p.xC, p.yC)] as const);
  // Directions in [0°, 360°), only where the slip is not negligible.
  const dir = (x: number, y: number): number => (((Math.atan2(y, x) * DEG) % 360) + 360) % 360;
  const phiI = pts.filter((p) => Math.hypot(p.xI, p.yI) > 1e-6).map((p) => [p.P, dir(p.xI, p.yI)] as const);
  const phiC = pts.filter((p) => Math.hypot(p.xC, p.yC) > 1e-6).map((p) => [p.P, dir(p.xC, p.yC)] as const);
  const vy = pts.map((p) => [p.P, p.vy] as const);
  const contacts: Span[] = [];
  const names = ['both slip', 'cushion rolls', 'table rolls', 'both roll'];
  for (const p of pts) {
    const name = names[(p.stickI ? 1 : 0) + (p.stickC ? 2 : 0)]!;
    const last = contacts[contacts.length - 1];
    if (last && last.label === name) contacts[contacts.length - 1] = { ...last, to: p.P };
    else contacts.push({ from: last ? last.to : p.P, to: p.P, label: name, color: name === 'both slip' ? '#1f77b4' : '#2ca02c' });
  }
  const pEnd = pts.length > 0 ? pts[pts.length - 1]!.P : 0;
  const turn = pts.find((p) => p.vy <= 0)?.P ?? pEnd;
  const halves: Span[] = [
    { from: 0, to: turn, label: 'compression', color: '#9467bd' },
    { from: turn, to: pEnd, label: 'restitution', color: '#ff7f0e' },
  ];
  const r = rebound(params, ball);
  const marks: Mark[] = [];
  const pub = PUBLISHED.find((p) => p.figure === 12 && p.V0 === ball.V0 && p.alpha === ball.alpha && p.kT === ball.kT && p.kS === ball.kS);
  if (pub) {
    marks.push({
      x: pEnd, y: -pub.speed * Math.sin(pub.angle / DEG), color: PALETTE[2],
      label: `published (${pub.label}): ${pub.speed} m/s at ${pub.angle}°; kernel: ${r.speed.toFixed(4)} m/s at ${r.angle.toFixed(3)}°`,
    });
  }
  const svg = figureSvg(
    `Fig. 12: slip against impulse, V0 = ${ball.V0} m/s, α = ${ball.alpha}°, ω_S = ${ball.kS} V0/R, ω_T = ${ball.kT} V0/R`,
    `${constants(params)}; rebound ${r.speed.toFixed(4)} m/s at ${r.angle.toFixed(3)}°`,
    [
      {
        title: 'Slip speeds', xLabel: 'impulse P at the cushion (N s)', yLabel: 'speed (m/s)', spans: contacts, marks,
        series: [
          { name: 's at I (cushion)', points: slipI, color: PALETTE[0] },
          { name: "s' at C (table)", points: slipC, color: PALETTE[1] },
          { name: 'v_y of the centre', points: vy, color: PALETTE[2], dash: '5 3' },
        ],
      },
      {
        title: 'Slip directions', xLabel: 'impulse P at the cushion (N s)', yLabel: 'slip direction (°, from the cushion line)',
        y: [0, 360], spans: halves,
        series: [
          { name: 'φ at I (cushion)', points: phiI, color: PALETTE[0] },
          { name: "φ' at C (table)", points: phiC, color: PALETTE[1] },
        ],
      },
    ],
  );
  return { svg, phases: { contacts, halves }, rebound: r };
}
