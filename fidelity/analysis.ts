// What the tracked shots show, measured the same way on the data and on the simulation: cushion
// rebounds (normal speed and angle in and out), the curvature of slow straight runs, and the cue
// ball's opening run.
import { sampleOutcome, type Outcome, type TableSpec } from '../shared/physics/index.ts';
import type { Track, TrackedShot } from './data.ts';
import { firstContactTime, fitStrike, openingError, sceneOf, simulateShot, type Strike } from './fit.ts';

export interface Rebound {
  /** Speeds toward and away from the cushion, and along it before and after (m/s). */
  readonly vin: number;
  readonly vout: number;
  readonly tin: number;
  readonly tout: number;
}

/** A finite difference over samples i..j whose span is at most this (s): no gap in the track. */
const MAX_SPAN = 0.09;

/**
 * The cushion rebounds of a track: a sample near a rail's contact line (within 15 mm, or a
 * frame's travel) that is a local extreme toward it, with velocities from the samples i-3, i-1
 * before and i+1, i+3 after, so that the sample nearest the contact, where the ball is turning,
 * is used by neither.
 */
export function cushionRebounds(b: Track, table: TableSpec): Rebound[] {
  const R = table.ballRadius;
  const out: Rebound[] = [];
  const axes = [[b.x, b.y, table.length / 2 - R], [b.y, b.x, table.width / 2 - R]] as const;
  for (let i = 3; i < b.t.length - 3; i++) {
    const t = b.t;
    if (t[i - 1]! - t[i - 3]! > MAX_SPAN || t[i + 3]! - t[i + 1]! > MAX_SPAN) continue;
    for (const [n, along, rail] of axes) {
      const sg = Math.sign(n[i]!);
      if (sg * n[i]! < sg * n[i - 1]! || sg * n[i]! < sg * n[i + 1]!) continue;
      const vin = sg * (n[i - 1]! - n[i - 3]!) / (t[i - 1]! - t[i - 3]!);
      // Within 15 mm of the rail, or of the distance covered in a frame.
      if (Math.abs(n[i]!) < rail - Math.max(0.015, vin * 0.02)) continue;
      const vout = -sg * (n[i + 3]! - n[i + 1]!) / (t[i + 3]! - t[i + 1]!);
      const tin = (along[i - 1]! - along[i - 3]!) / (t[i - 1]! - t[i - 3]!);
      const tout = (along[i + 3]! - along[i + 1]!) / (t[i + 3]! - t[i + 1]!);
      if (vin > 0.05 && vout > 0) out.push({ vin, vout, tin, tout });
    }
  }
  return out;
}

/**
 * A simulated ball as the data would track it: sampled at the data's times from t0 on (times are
 * the data's, so already on its 0.02 s grid), positions rounded to 1 mm, a sample within 2 mm of
 * the last kept one dropped.
 */
export function trackedAs(out: Outcome, id: string, times: readonly number[], t0: number, table: TableSpec): Track {
  const k = { t: [] as number[], x: [] as number[], y: [] as number[] };
  for (const t of times) {
    if (t < t0) continue;
    const p = sampleOutcome(out, t - t0, table).find((q) => q.id === id)!;
    const x = Math.round(p.x * 1000) / 1000;
    const y = Math.round(p.y * 1000) / 1000;
    const j = k.t.length - 1;
    if (j >= 0 && Math.hypot(x - k.x[j]!, y - k.y[j]!) < 0.002) continue;
    k.t.push(t);
    k.x.push(x);
    k.y.push(y);
  }
  return k;
}

/** x with A x = r, for a small dense system (Gaussian elimination, partial pivoting). */
function solve(A: number[][], r: number[]): number[] {
  const n = r.length;
  const a = A.map((row, i) => [...row, r[i]!]);
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let i = c + 1; i < n; i++) if (Math.abs(a[i]![c]!) > Math.abs(a[p]![c]!)) p = i;
    [a[c], a[p]] = [a[p]!, a[c]!];
    for (let i = c + 1; i < n; i++) {
      const f = a[i]![c]! / a[c]![c]!;
      for (let k = c; k <= n; k++) a[i]![k]! -= f * a[c]![k]!;
    }
  }
  const x = new Array<number>(n).fill(0);
  for (let c = n - 1; c >= 0; c--) {
    let v = a[c]![n]!;
    for (let k = c + 1; k < n; k++) v -= a[c]![k]! * x[k]!;
    x[c] = v / a[c]![c]!;
  }
  return x;
}

export interface SlowRuns {
  /** One-second windows of a slow straight run (0.1-0.6 m/s, away from the rails). */
  readonly windows: number;
  /** The deceleration along the motion and a constant acceleration (a table's slope), m/s². */
  readonly decel: number;
  readonly slope: readonly [number, number];
  /** Mean |acceleration across the motion| (m/s²): what bends a slow ball's path. */
  readonly across: number;
}

/**
 * The accelerations of slow balls: every one-second window of a track away from the rails
 * (3 cm clear) with at least 20 samples, a quadratic fitted per coordinate, kept when it
 * fits within 4 mm and its speed is 0.1-0.6 m/s; then a = -d u + s fitted over all windows
 * (u the direction of motion): d the cloth's deceleration, s a slope common to the table.
 */
export function slowRuns(tracks: readonly Track[], table: TableSpec): SlowRuns {
  const xMax = table.length / 2 - table.ballRadius - 0.03;
  const yMax = table.width / 2 - table.ballRadius - 0.03;
  const rows: { ux: number; uy: number; ax: number; ay: number }[] = [];
  for (const b of tracks) {
    for (let i = 0; i < b.t.length; i += 5) {
      const idx: number[] = [];
      for (let j = i; j < b.t.length && b.t[j]! <= b.t[i]! + 1; j++) idx.push(j);
      if (idx.length < 20 || b.t[idx[idx.length - 1]!]! - b.t[i]! < 0.9) continue;
      if (idx.some((j) => Math.abs(b.x[j]!) > xMax || Math.abs(b.y[j]!) > yMax)) continue;
      const tm = b.t[i]! + 0.5;
      const S = [0, 0, 0, 0, 0];
      const rx = [0, 0, 0];
      const ry = [0, 0, 0];
      for (const j of idx) {
        const t = b.t[j]! - tm;
        for (let k = 0; k < 5; k++) S[k]! += t ** k;
        for (let k = 0; k < 3; k++) {
          rx[k]! += t ** k * b.x[j]!;
          ry[k]! += t ** k * b.y[j]!;
        }
      }
      const M = [[S[0]!, S[1]!, S[2]!], [S[1]!, S[2]!, S[3]!], [S[2]!, S[3]!, S[4]!]];
      const cx = solve(M, rx);
      const cy = solve(M, ry);
      const v = Math.hypot(cx[1]!, cy[1]!);
      if (v < 0.1 || v > 0.6) continue;
      const misfit = Math.max(...idx.map((j) => {
        const t = b.t[j]! - tm;
        return Math.hypot(cx[0]! + cx[1]! * t + cx[2]! * t * t - b.x[j]!, cy[0]! + cy[1]! * t + cy[2]! * t * t - b.y[j]!);
      }));
      if (misfit > 0.004) continue;
      rows.push({ ux: cx[1]! / v, uy: cy[1]! / v, ax: 2 * cx[2]!, ay: 2 * cy[2]! });
    }
  }
  // Normal equations of a = -d u + s, unknowns (d, sx, sy).
  const A = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  const r = [0, 0, 0];
  for (const w of rows) {
    for (const [c, a] of [[[-w.ux, 1, 0], w.ax], [[-w.uy, 0, 1], w.ay]] as const) {
      for (let i = 0; i < 3; i++) {
        r[i]! += c[i]! * a;
        for (let j = 0; j < 3; j++) A[i]![j]! += c[i]! * c[j]!;
      }
    }
  }
  const [d, sx, sy] = rows.length > 3 ? solve(A, r) : [NaN, NaN, NaN];
  const across = rows.reduce((a, w) => a + Math.abs(-w.uy * w.ax + w.ux * w.ay), 0) / rows.length;
  return { windows: rows.length, decel: d!, slope: [sx!, sy!], across };
}

/**
 * The cue ball's error before the first simulated ball-ball contact, split along and across its
 * tracked motion (RMS, m): along is timing (speed, t0), across is line (heading, swerve).
 */
export function openingAlongAcross(cue: Track, out: Outcome, t0: number, table: TableSpec): { along: number; across: number } {
  const contact = out.events.find((e) => e.kind === 'ball')?.t ?? Infinity;
  let along = 0;
  let across = 0;
  let n = 0;
  for (let i = 0; i < cue.t.length; i++) {
    const dt = cue.t[i]! - t0;
    if (dt < 0 || dt >= contact) continue;
    const p = sampleOutcome(out, dt, table).find((q) => q.id === 'white')!;
    const j = Math.min(i + 1, cue.t.length - 1);
    const k = Math.max(i - 1, 0);
    const dx = cue.x[j]! - cue.x[k]!;
    const dy = cue.y[j]! - cue.y[k]!;
    const d = Math.hypot(dx, dy);
    if (!(d > 0)) continue;
    const ex = p.x - cue.x[i]!;
    const ey = p.y - cue.y[i]!;
    along += ((ex * dx + ey * dy) / d) ** 2;
    across += ((ex * dy - ey * dx) / d) ** 2;
    n++;
  }
  return n === 0 ? { along: NaN, across: NaN } : { along: Math.sqrt(along / n), across: Math.sqrt(across / n) };
}

/**
 * The cue ball's opening run (its tracked samples before the first object ball moves) under a
 * shot's strike and under a strike fitted to that run alone: each one's RMS error on the run (m),
 * and the ratio of the cue ball's speeds at the simulated first ball-ball contact (alone over
 * the shot's). A ratio above 1 says the whole shot fits best with a cue ball slower at the
 * contact than its own opening shows. Null without an opening run or a contact.
 */
export function openingRun(s: TrackedShot, strike: Strike, table: TableSpec): { whole: number; alone: number; speedRatio: number } | null {
  const until = firstContactTime(s);
  if (!Number.isFinite(until)) return null;
  const alone = fitStrike(s, table, strike, 150, until);
  const scene = sceneOf(s);
  const speedAtContact = (st: Strike): number => {
    const out = simulateShot(s, scene, st, table);
    const contact = out?.events.find((e) => e.kind === 'ball');
    if (!out || !contact) return NaN;
    const cue = sampleOutcome(out, contact.t - 1e-9, table).find((q) => q.id === 'white')!;
    return Math.hypot(cue.vx, cue.vy);
  };
  const ratio = speedAtContact(alone.strike) / speedAtContact(strike);
  return Number.isFinite(ratio) ? { whole: openingError(s, scene, strike, table, until), alone: alone.rms, speedRatio: ratio } : null;
}
