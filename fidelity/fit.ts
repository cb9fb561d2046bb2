// Fitting the simulation to tracked shots: each shot's strike (heading, speed, tip offsets and the
// strike's time), and the carom table's physical constants on a set of shots.
import { MiscueError, tableSpec, type Outcome, type Scene, type Shot, type TableSpec } from '../shared/physics/index.ts';
import { sampleOutcome } from '../shared/physics/index.ts';
import { simulateOn } from '../shared/physics/diagnostics.ts';
import type { TrackedShot } from './data.ts';
import { nelderMead } from './nelder-mead.ts';

export const TABLE = tableSpec('carom-match');
/** The simulation's ids of the cue ball and the two others, in the data's order. */
const SIM_IDS = ['white', 'yellow', 'red'] as const;
/** The error charged to a strike the model refuses (a miscue) or a failed simulation (m). */
const REFUSED = 5;
/** A shot whose best strike still misses by more than this RMS (m) is one the model cannot express. */
export const NOT_EXPRESSED = 0.15;

export interface Strike {
  readonly heading: number;
  readonly speed: number;
  readonly side: number;
  readonly top: number;
  /** The data's time of the strike (s). */
  readonly t0: number;
}

/** Data ball id -> simulation ball id: the cue ball first, the others in the data's order. */
export function ballMap(s: TrackedShot): Record<string, string> {
  const others = Object.keys(s.balls).sort().filter((id) => id !== s.cue);
  return { [s.cue]: SIM_IDS[0], [others[0]!]: SIM_IDS[1], [others[1]!]: SIM_IDS[2] };
}

/** The scene at the strike: each ball where the data first sees it, moved apart if they overlap. */
export function sceneOf(s: TrackedShot): Scene {
  const map = ballMap(s);
  const R = TABLE.ballRadius;
  const xMax = TABLE.length / 2 - R - 1e-4;
  const yMax = TABLE.width / 2 - R - 1e-4;
  const balls = Object.keys(s.balls).sort().map((id) => {
    const b = s.balls[id]!;
    return { id: map[id]!, x: Math.max(-xMax, Math.min(xMax, b.x[0]!)), y: Math.max(-yMax, Math.min(yMax, b.y[0]!)) };
  });
  // Two balls closer than 2R (tracking noise) are pushed apart along their line.
  for (let i = 0; i < balls.length; i++) {
    for (let j = i + 1; j < balls.length; j++) {
      const a = balls[i]!;
      const b = balls[j]!;
      const dx = b.x - a.x;
      const dy = b.y - a.y;
      const d = Math.hypot(dx, dy);
      const gap = 2 * R + 1e-4 - d;
      if (gap > 0 && d > 0) {
        a.x -= (dx / d) * gap / 2;
        a.y -= (dy / d) * gap / 2;
        b.x += (dx / d) * gap / 2;
        b.y += (dy / d) * gap / 2;
      }
    }
  }
  return { table: 'carom-match', balls };
}

/** The window of the strike's time: within 0.1 s of the cue ball's first move (its first two samples). */
export function t0Range(s: TrackedShot): [number, number] {
  const t = s.balls[s.cue]!.t;
  return [Math.max(t[0]!, t[1]! - 0.1), t[1]!];
}

export function shotOf(st: Strike): Shot {
  return { ball: SIM_IDS[0], heading: st.heading, speed: st.speed, side: st.side, top: st.top };
}

/** The simulated paths, or null when the model refuses the strike. */
export function simulateShot(s: TrackedShot, scene: Scene, st: Strike, table: TableSpec): Outcome | null {
  try {
    return simulateOn(table, scene, shotOf(st));
  } catch (err) {
    if (err instanceof MiscueError || (err as Error).name === 'SimulationInputError') return null;
    throw err;
  }
}

/** Squared distances between the simulated and tracked balls at every tracked time t >= t0. */
export function residuals(s: TrackedShot, out: Outcome, t0: number, table: TableSpec): { t: number; d2: number }[] {
  const map = ballMap(s);
  const times = new Set<number>();
  for (const b of Object.values(s.balls)) for (const t of b.t) if (t >= t0) times.add(t);
  const at = new Map<number, Map<string, { x: number; y: number }>>();
  for (const t of times) at.set(t, new Map(sampleOutcome(out, t - t0, table).map((b) => [b.id, b])));
  const r: { t: number; d2: number }[] = [];
  for (const [id, b] of Object.entries(s.balls)) {
    b.t.forEach((t, i) => {
      if (t < t0) return;
      const p = at.get(t)!.get(map[id]!)!;
      r.push({ t, d2: (p.x - b.x[i]!) ** 2 + (p.y - b.y[i]!) ** 2 });
    });
  }
  return r;
}

/** RMS distance (m) over all three balls at the tracked times, for a strike on a table. */
export function rmsError(s: TrackedShot, scene: Scene, st: Strike, table: TableSpec): number {
  const out = simulateShot(s, scene, st, table);
  if (out === null) return REFUSED;
  const r = residuals(s, out, st.t0, table);
  return r.length === 0 ? 0 : Math.sqrt(r.reduce((a, x) => a + x.d2, 0) / r.length);
}

/**
 * The data's time of the first ball-ball contact, near enough: the last tracked time before an
 * object ball's first move (its second sample; a ball at rest keeps only two samples).
 */
export function firstContactTime(s: TrackedShot): number {
  let t = Infinity;
  for (const [id, b] of Object.entries(s.balls)) {
    if (id === s.cue || b.t.length < 3) continue;
    t = Math.min(t, b.t[1]! - 0.02);
  }
  return t;
}

/** RMS distance (m) of the cue ball alone at the tracked times in [t0, until): its opening run. */
export function openingError(s: TrackedShot, scene: Scene, st: Strike, table: TableSpec, until: number): number {
  const out = simulateShot(s, scene, st, table);
  if (out === null) return REFUSED;
  const b = s.balls[s.cue]!;
  let sum = 0;
  let n = 0;
  for (let i = 0; i < b.t.length; i++) {
    const t = b.t[i]!;
    if (t < st.t0) continue;
    if (t >= until) break;
    const p = sampleOutcome(out, t - st.t0, table).find((q) => q.id === SIM_IDS[0])!;
    sum += (p.x - b.x[i]!) ** 2 + (p.y - b.y[i]!) ** 2;
    n++;
  }
  return n === 0 ? 0 : Math.sqrt(sum / n);
}

/** A first guess from the cue ball's first frames: heading and speed of its first move. */
export function seedStrike(s: TrackedShot): Strike {
  const b = s.balls[s.cue]!;
  const k = b.t.length > 2 ? 2 : 1;
  const dx = b.x[k]! - b.x[k - 1]!;
  const dy = b.y[k]! - b.y[k - 1]!;
  const dt = b.t[k]! - b.t[k - 1]! || 0.02;
  const [lo, hi] = t0Range(s);
  return { heading: Math.atan2(dy, dx), speed: Math.min(8, Math.max(0.3, Math.hypot(dx, dy) / dt)), side: 0, top: 0.2, t0: (lo + hi) / 2 };
}

/** The strike that best reproduces the shot on the table: Nelder-Mead from the seed, restarted once. */
export function fitStrike(
  s: TrackedShot, table: TableSpec, seed: Strike = seedStrike(s), evaluations = 300, until?: number,
): { strike: Strike; rms: number } {
  const scene = sceneOf(s);
  const [lo, hi] = t0Range(s);
  const strikeOf = (x: number[]): Strike => ({ heading: x[0]!, speed: x[1]!, side: x[2]!, top: x[3]!, t0: x[4]! });
  const cost = (x: number[]): number => {
    const st = strikeOf(x);
    // Outside the model's range: the distance outside, on top of a refused strike's error.
    const tip = Math.hypot(st.side, st.top);
    const out = Math.max(0, tip - 0.5) + Math.max(0, lo - st.t0) + Math.max(0, st.t0 - hi) + Math.max(0, 0.05 - st.speed);
    if (out > 0) return REFUSED + out;
    return until === undefined ? rmsError(s, scene, st, table) : openingError(s, scene, st, table, until);
  };
  let x = [seed.heading, seed.speed, seed.side, seed.top, Math.min(hi, Math.max(lo, seed.t0))];
  let best = { x, f: cost(x), evaluations: 0 };
  for (const scale of [1, 0.3]) {
    const m = nelderMead(cost, best.x, [0.03 * scale, 0.25 * best.x[1]! * scale, 0.2 * scale, 0.2 * scale, 0.02 * scale], evaluations);
    if (m.f < best.f) best = m;
  }
  x = best.x;
  return { strike: strikeOf(x), rms: best.f };
}

/** The carom table's constants the fit varies, as a vector, and back. */
export const CONSTANTS = ['muSlide', 'muRoll', 'spinDecel', 'cushionRestitution', 'cushionFriction', 'cushionHeightR', 'ballRestitution', 'ballFrictionScale'] as const;

/** Alciatore's ball-ball friction law μ(v) = a + b e^(-c v) (TP A-14): the scale's reference. */
const ALCIATORE = { a: 9.951e-3, b: 0.108 };

export function constantsOf(t: TableSpec): number[] {
  return [t.cloth.muSlide, t.cloth.muRoll, t.cloth.spinDecel, t.cushion.restitution, t.cushion.friction, t.cushion.height / t.ballRadius, t.ballBall.restitution, t.ballBall.frictionA / ALCIATORE.a];
}

/** The table with the given constants (null outside their physical ranges). */
export function tableWith(base: TableSpec, c: readonly number[]): TableSpec | null {
  const [muSlide, muRoll, spinDecel, ee, muW, hR, e, fk] = c as [number, number, number, number, number, number, number, number];
  const ok = muSlide > 0.02 && muSlide < 0.6 && muRoll > 5e-4 && muRoll < 0.05 && spinDecel > 0.5 && spinDecel < 60 &&
    ee > 0.3 && ee <= 1 && muW >= 0 && muW < 0.6 && hR > 1.05 && hR < 1.9 && e > 0.6 && e <= 1 && fk > 0 && fk < 5;
  if (!ok) return null;
  const R = base.ballRadius;
  return {
    ...base,
    cushionHeight: hR * R,
    cloth: { muSlide, muRoll, spinDecel },
    // (The restitution's fall with speed, if the base table has one, is kept.)
    cushion: { ...base.cushion, height: hR * R, restitution: ee, friction: muW },
    ballBall: { ...base.ballBall, restitution: e, frictionA: ALCIATORE.a * fk, frictionB: ALCIATORE.b * fk },
  };
}

export function percentile(xs: readonly number[], p: number): number {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor((p / 100) * s.length))]!;
}

/**
 * Where a shot's error lies: the RMS distance over the tracked times before the simulated cue
 * ball's first contact with another ball, from then until 3 s after the strike, and after that
 * (late rolling); NaN for a phase without samples.
 */
export function errorByPhase(s: TrackedShot, out: Outcome, t0: number, table: TableSpec): { first: number; middle: number; late: number } {
  const contact = out.events.find((e) => e.kind === 'ball')?.t ?? Infinity;
  const r = residuals(s, out, t0, table);
  const rms = (keep: (dt: number) => boolean): number => {
    const xs = r.filter((x) => keep(x.t - t0));
    return xs.length > 0 ? Math.sqrt(xs.reduce((a, x) => a + x.d2, 0) / xs.length) : NaN;
  };
  return { first: rms((dt) => dt < contact), middle: rms((dt) => dt >= contact && dt < 3), late: rms((dt) => dt >= contact && dt >= 3) };
}
