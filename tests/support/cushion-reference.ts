// A converged reference for the cushion impact (Mathavan, Jackson and Parkin 2010), written
// independently of the kernel in shared/physics: physical variables (v, ω, W, P), a fixed-step
// classical Runge-Kutta (RK4) at a very fine step, every event (slip reaching zero, a rolling
// contact leaving its friction cone, vy = 0, the work target) located by bisection on the
// length of a re-integrated step, the rolling frictions (eqs. 15a/15b) solved numerically from
// the generic slip rates, and the direction a slip takes from zero found by a scan over angles.
// Same model and the same documented outcomes as the kernel (docs/cushion.md). Slow on purpose.
import type { CushionParams, CushionState } from '../../shared/physics/index.ts';

export interface ReferenceResult {
  readonly state: { vx: number; vy: number; wx: number; wy: number; wz: number };
  readonly outcome: 'no-impact' | 'restitution' | 'stalled';
  /** Total impulse at the cushion (N s). */
  readonly impulse: number;
  /** Number of slip-zero events met. */
  readonly zeroEvents: number;
}

type Vec = number[]; // [vx, vy, wx, wy, wz, W]

/** cos 1°: a reference step may turn a slip direction by at most this much. */
const COS_MAX_TURN = Math.cos(Math.PI / 180);

interface Ctx {
  M: number;
  R: number;
  s: number;
  c: number;
  muS: number;
  muW: number;
  stickI: boolean;
  stickC: boolean;
  // Direction used by a slipping contact whose slip (minus its offset) is tiny.
  dirI: [number, number];
  dirC: [number, number];
  offI: [number, number];
  offC: [number, number];
  tiny: number;
  /**
   * A slip growing from zero is stiff (its direction relaxes at a rate ~ 1/slip): while it is
   * below SLAVE_LIMIT × V0 it takes the direction its rates enforce, re-solved every step.
   */
  slaveI: boolean;
  slaveC: boolean;
}

/** Slip (fraction of V0) up to which a slip growing from zero is slaved to its rates. */
const SLAVE_LIMIT = 1e-5;

function slips(ctx: Ctx, y: Vec): [number, number, number, number] {
  const { R, s, c } = ctx;
  const [vx, vy, wx, wy, wz] = y as [number, number, number, number, number];
  return [
    vx + wy * R * s - wz * R * c - ctx.offI[0],
    -vy * s + wx * R - ctx.offI[1],
    vx - wy * R - ctx.offC[0],
    vy + wx * R - ctx.offC[1],
  ];
}

/** dy/dP for frictions g (at I, basis e_x, t) and h (at C), per unit impulse at I. */
function rates(ctx: Ctx, y: Vec, g: [number, number], h: [number, number]): Vec {
  const { M, R, s, c } = ctx;
  // Forces per unit P: normal at I (0, -c, -s), friction at I g0 e_x + g1 (0, -s, c),
  // table friction (h0, h1, 0); torques r × F with r_I = R (0, c, s), r_C = R (0, 0, -1).
  const Fx = g[0] + h[0];
  const Fy = -c - s * g[1] + h[1];
  const k = 1 / (0.4 * M * R * R);
  // r_I × F_I + r_C × F_C, with F_I = (g0, -c - s g1, -s + c g1), F_C = (h0, h1, A)
  const FIx = g[0];
  const FIy = -c - s * g[1];
  const FIz = -s + c * g[1];
  const tx = R * (c * FIz - s * FIy) + R * h[1];
  const ty = R * (s * FIx) - R * h[0];
  const tz = -R * c * FIx;
  return [Fx / M, Fy / M, k * tx, k * ty, k * tz, c * y[1]!];
}

/** Slip rates at I and C (d/dP) for frictions g, h. */
function slipRates(ctx: Ctx, y: Vec, g: [number, number], h: [number, number]): [number, number, number, number] {
  const d = rates(ctx, y, g, h);
  const { R, s, c } = ctx;
  return [
    d[0]! + d[3]! * R * s - d[4]! * R * c,
    -d[1]! * s + d[2]! * R,
    d[0]! - d[3]! * R,
    d[1]! + d[2]! * R,
  ];
}

function unit(x: number, y: number, fallback: [number, number], tiny: number): [number, number] {
  const r = Math.sqrt(x * x + y * y);
  return r > tiny ? [x / r, y / r] : fallback;
}

/** Table normal per unit P for friction g at I (the table pushes, never pulls). */
function tableNormal(ctx: Ctx, g: [number, number]): number {
  return Math.max(0, ctx.s - ctx.c * g[1]);
}

function solve2(a: number, b: number, c: number, d: number, r0: number, r1: number): [number, number] {
  const det = a * d - b * c;
  return [(r0 * d - b * r1) / det, (a * r1 - c * r0) / det];
}

/** Frictions (g, h) in the current modes. */
function frictions(ctx: Ctx, y: Vec): { g: [number, number]; h: [number, number] } {
  const [xI, yI, xC, yC] = slips(ctx, y);
  const uI = ctx.slaveI ? ctx.dirI : unit(xI, yI, ctx.dirI, ctx.tiny);
  const uC = ctx.slaveC ? ctx.dirC : unit(xC, yC, ctx.dirC, ctx.tiny);
  if (!ctx.stickI && !ctx.stickC) {
    const g: [number, number] = [-ctx.muW * uI[0], -ctx.muW * uI[1]];
    const n = tableNormal(ctx, g);
    return { g, h: [-ctx.muS * n * uC[0], -ctx.muS * n * uC[1]] };
  }
  if (!ctx.stickI && ctx.stickC) {
    // g fixed; C's slip rates are affine in h: solve rates_C(h) = 0.
    const g: [number, number] = [-ctx.muW * uI[0], -ctx.muW * uI[1]];
    const r0 = slipRates(ctx, y, g, [0, 0]);
    const r1 = slipRates(ctx, y, g, [1, 0]);
    const r2 = slipRates(ctx, y, g, [0, 1]);
    const h = solve2(r1[2] - r0[2], r2[2] - r0[2], r1[3] - r0[3], r2[3] - r0[3], -r0[2], -r0[3]);
    return { g, h };
  }
  if (ctx.stickI && !ctx.stickC) {
    // h = -μs N(g) u_C; I's slip rates are affine in g: solve rates_I(g) = 0.
    const hOf = (g: [number, number]): [number, number] => {
      const n = ctx.s - ctx.c * g[1]; // affine (unclamped) for the solve
      return [-ctx.muS * n * uC[0], -ctx.muS * n * uC[1]];
    };
    const z: [number, number] = [0, 0];
    const ex: [number, number] = [1, 0];
    const ey: [number, number] = [0, 1];
    const r0 = slipRates(ctx, y, z, hOf(z));
    const r1 = slipRates(ctx, y, ex, hOf(ex));
    const r2 = slipRates(ctx, y, ey, hOf(ey));
    const g = solve2(r1[0] - r0[0], r2[0] - r0[0], r1[1] - r0[1], r2[1] - r0[1], -r0[0], -r0[1]);
    return { g, h: hOf(g) };
  }
  // Both stick: 4 unknowns (g0, g1, h0, h1), all slip rates zero. Gaussian elimination.
  const base = slipRates(ctx, y, [0, 0], [0, 0]);
  const cols: number[][] = [];
  const units: [[number, number], [number, number]][] = [
    [[1, 0], [0, 0]],
    [[0, 1], [0, 0]],
    [[0, 0], [1, 0]],
    [[0, 0], [0, 1]],
  ];
  for (const [g, h] of units) {
    const r = slipRates(ctx, y, g, h);
    cols.push(r.map((v, i) => v - base[i]!));
  }
  const A = [0, 1, 2, 3].map((i) => [cols[0]![i]!, cols[1]![i]!, cols[2]![i]!, cols[3]![i]!, -base[i]!]);
  for (let k = 0; k < 4; k++) {
    let p = k;
    for (let i = k + 1; i < 4; i++) if (Math.abs(A[i]![k]!) > Math.abs(A[p]![k]!)) p = i;
    [A[k], A[p]] = [A[p]!, A[k]!];
    for (let i = 0; i < 4; i++) {
      if (i === k) continue;
      const f = A[i]![k]! / A[k]![k]!;
      for (let j = k; j < 5; j++) A[i]![j]! -= f * A[k]![j]!;
    }
  }
  const x = A.map((row, i) => row[4]! / row[i]!);
  return { g: [x[0]!, x[1]!], h: [x[2]!, x[3]!] };
}

function deriv(ctx: Ctx, y: Vec): Vec {
  const { g, h } = frictions(ctx, y);
  return rates(ctx, y, g, h);
}

/** Friction-cone excess of the stuck contacts (> 0: cannot stay stuck). */
function stickExcess(ctx: Ctx, y: Vec): number {
  const { g, h } = frictions(ctx, y);
  let m = -Infinity;
  const n = ctx.s - ctx.c * g[1];
  if (ctx.stickI) {
    m = Math.max(m, Math.hypot(g[0], g[1]) - ctx.muW);
    if (!ctx.stickC && !(n > 0)) m = Math.max(m, 1);
  }
  if (ctx.stickC) m = Math.max(m, Math.hypot(h[0], h[1]) - ctx.muS * Math.max(0, n));
  return m;
}

function rk4(ctx: Ctx, y: Vec, h: number, watch: { dotI: number; dotC: number; refI: [number, number]; refC: [number, number] } | null): Vec {
  const add = (a: Vec, b: Vec, f: number): Vec => a.map((v, i) => v + f * b[i]!);
  const ev = (z: Vec): Vec => {
    if (watch && z !== y) {
      // Cosine of the angle between each stage's slip and the step's starting direction.
      const [xI, yI, xC, yC] = slips(ctx, z);
      watch.dotI = Math.min(watch.dotI, (xI * watch.refI[0] + yI * watch.refI[1]) / Math.hypot(xI, yI));
      watch.dotC = Math.min(watch.dotC, (xC * watch.refC[0] + yC * watch.refC[1]) / Math.hypot(xC, yC));
    }
    return deriv(ctx, z);
  };
  const k1 = ev(y);
  const k2 = ev(add(y, k1, h / 2));
  const k3 = ev(add(y, k2, h / 2));
  const k4 = ev(add(y, k3, h));
  return y.map((v, i) => v + (h / 6) * (k1[i]! + 2 * k2[i]! + 2 * k3[i]! + k4[i]!));
}

/**
 * Direction u (unit) in which a slip leaves zero: its rates with friction -μ u must point along
 * u, rate(u) = λ u with λ >= 0. Found by scanning angles for a sign change of cross(rate, u)
 * with positive projection, then bisection. rateOf(u) gives the slip rate for direction u.
 */
function onsetDirection(rateOf: (u: [number, number]) => [number, number]): [number, number] {
  const N = 720;
  const cross = (a: number): { x: number; dot: number } => {
    const u: [number, number] = [Math.cos(a), Math.sin(a)];
    const r = rateOf(u);
    return { x: r[0] * u[1] - r[1] * u[0], dot: r[0] * u[0] + r[1] * u[1] };
  };
  let best: [number, number] | null = null;
  let bestDot = -Infinity;
  let prev = cross(0);
  for (let i = 1; i <= N; i++) {
    const a1 = (2 * Math.PI * i) / N;
    const cur = cross(a1);
    if (prev.x === 0 || prev.x * cur.x < 0) {
      let lo = (2 * Math.PI * (i - 1)) / N;
      let hi = a1;
      const slo = Math.sign(prev.x);
      for (let k = 0; k < 60; k++) {
        const mid = 0.5 * (lo + hi);
        if (Math.sign(cross(mid).x) === slo && slo !== 0) lo = mid;
        else hi = mid;
      }
      const a = 0.5 * (lo + hi);
      const d = cross(a).dot;
      // (λ >= 0; at the edge of the cone λ = 0 and roundoff may make it slightly negative.)
      if (d > bestDot) {
        bestDot = d;
        best = [Math.cos(a), Math.sin(a)];
      }
    }
    prev = cur;
  }
  if (best === null) throw new Error('reference: no onset direction');
  return best;
}

/** A slip (or both) is zero: decide the modes. True when both contacts stick. */
function decide(ctx: Ctx, y: Vec, zI: boolean, zC: boolean): boolean {
  const atI = zI || ctx.stickI;
  const atC = zC || ctx.stickC;
  if (atI && atC) {
    ctx.stickI = true;
    ctx.stickC = true;
    if (stickExcess(ctx, y) <= 0) return true;
    // C rolls, I slips from zero (its rates with C rolling), if C's cone allows it.
    ctx.stickI = false;
    ctx.slaveI = true;
    const dir = onsetDirection((u) => {
      ctx.dirI = u;
      const { g, h } = frictions(ctx, y);
      const r = slipRates(ctx, y, g, h);
      return [r[0], r[1]];
    });
    ctx.dirI = dir;
    if (stickExcess(ctx, y) <= 0) return false;
    // I rolls, C slips along -y (opposite to the friction it would need to roll), if I's cone
    // allows it: in a head-on impact whose cushion contact rolls through the end of compression
    // both slips reach zero together, and this is the continuation that impacts a hair off
    // head-on take (without it the exactly head-on one stalled where those rebound).
    ctx.stickI = true;
    ctx.slaveI = false;
    ctx.stickC = false;
    ctx.slaveC = true;
    ctx.dirC = [0, -1];
    if (stickExcess(ctx, y) <= 0) return false;
    ctx.stickI = false;
    ctx.slaveI = true;
    ctx.dirI = [0, 1];
    return false;
  }
  if (zC) {
    ctx.stickC = true;
    if (stickExcess(ctx, y) <= 0) return false;
    ctx.stickC = false;
    ctx.slaveC = true;
    ctx.dirC = onsetDirection((u) => {
      ctx.dirC = u;
      const { g, h } = frictions(ctx, y);
      const r = slipRates(ctx, y, g, h);
      return [r[2], r[3]];
    });
    return false;
  }
  ctx.stickI = true;
  if (stickExcess(ctx, y) <= 0) return false;
  ctx.stickI = false;
  ctx.slaveI = true;
  ctx.dirI = onsetDirection((u) => {
    ctx.dirI = u;
    const { g, h } = frictions(ctx, y);
    const r = slipRates(ctx, y, g, h);
    return [r[0], r[1]];
  });
  return false;
}

/** pred(0) false, pred(1) true: the bracket [lo, hi] of the switch after `iterations` halvings. */
function bisect(pred: (t: number) => boolean, iterations = 60): { lo: number; hi: number } {
  let lo = 0;
  let hi = 1;
  for (let i = 0; i < iterations; i++) {
    const mid = 0.5 * (lo + hi);
    if (pred(mid)) hi = mid;
    else lo = mid;
  }
  return { lo, hi };
}

/**
 * The reference rebound. `steps` is the number of RK4 steps per M vy0 / cos θ of impulse (the
 * frictionless compression impulse); the default 4000 is converged far below 1e-9 V0 (see
 * tests/unit/cushion-reference.test.ts, which halves it).
 */
export function referenceRebound(state: CushionState, params: CushionParams, steps = 4000): ReferenceResult {
  const { M, R, h: hh, ee, muS, muW } = params;
  if (!(state.vy > 0)) return { state: { ...state }, outcome: 'no-impact', impulse: 0, zeroEvents: 0 };
  const s = (hh - R) / R;
  const c = Math.sqrt(1 - s * s);
  const V = Math.hypot(state.vx, state.vy);
  const ctx: Ctx = {
    M, R, s, c, muS, muW,
    stickI: false, stickC: false,
    dirI: [1, 0], dirC: [1, 0], offI: [0, 0], offC: [0, 0],
    tiny: 1e-14 * V,
    slaveI: false,
    slaveC: false,
  };
  let y: Vec = [state.vx, state.vy, state.wx, state.wy, state.wz, 0];
  const dP = (M * state.vy) / c / steps;
  let P = 0;
  let zeroEvents = 0;
  let compressing = true;
  let wEnd = 0;
  const zeroTol = 1e-12 * V;
  const zeroEvent = (zI: boolean, zC: boolean): boolean => {
    zeroEvents++;
    const [xI, yI, xC, yC] = slips({ ...ctx, offI: [0, 0], offC: [0, 0] }, y);
    if (zI) ctx.offI = [xI, yI];
    if (zC) ctx.offC = [xC, yC];
    if (zI) ctx.slaveI = false;
    if (zC) ctx.slaveC = false;
    return decide(ctx, y, zI, zC);
  };
  const finish = (outcome: 'restitution' | 'stalled'): ReferenceResult => ({
    state: { vx: y[0]!, vy: outcome === 'stalled' ? 0 : y[1]!, wx: y[2]!, wy: y[3]!, wz: y[4]! },
    outcome,
    impulse: P,
    zeroEvents,
  });
  {
    const [xI, yI, xC, yC] = slips(ctx, y);
    const zI = Math.hypot(xI, yI) <= zeroTol;
    const zC = Math.hypot(xC, yC) <= zeroTol;
    if ((zI || zC) && zeroEvent(zI, zC)) return finish('stalled');
  }
  const maxSteps = 1000 * steps;
  let h = dP;
  for (let n = 0; n < maxSteps; n++) {
    for (const which of [0, 1] as const) {
      const slaved = which === 0 ? ctx.slaveI : ctx.slaveC;
      if (!slaved) continue;
      const e = slips(ctx, y);
      const rho = which === 0 ? Math.hypot(e[0], e[1]) : Math.hypot(e[2], e[3]);
      if (rho > SLAVE_LIMIT * V || (which === 1 && ctx.stickI)) {
        if (which === 0) ctx.slaveI = false;
        else ctx.slaveC = false;
        continue;
      }
      const dir = onsetDirection((u) => {
        if (which === 0) ctx.dirI = u;
        else ctx.dirC = u;
        const { g, h } = frictions(ctx, y);
        const r = slipRates(ctx, y, g, h);
        return which === 0 ? [r[0], r[1]] : [r[2], r[3]];
      });
      if (which === 0) ctx.dirI = dir;
      else ctx.dirC = dir;
    }
    const [xI, yI, xC, yC] = slips(ctx, y);
    const refI = unit(xI, yI, ctx.dirI, ctx.tiny);
    const refC = unit(xC, yC, ctx.dirC, ctx.tiny);
    // Does a step of length u turn a slipping contact's slip by more than 1° (at any stage)?
    // Then the step is halved until it does not (fast turns, as when a slip passes close to
    // zero, are integrated at a fine step) or until it is negligible: then the slip is at
    // zero (located by Newton steps below).
    // (A slip that starts from zero takes its onset direction only to first order: no check.)
    const watchI = !ctx.stickI && !ctx.slaveI && Math.hypot(xI, yI) > zeroTol;
    const watchC = !ctx.stickC && !ctx.slaveC && Math.hypot(xC, yC) > zeroTol;
    const step = (u: number): { y: Vec; I: boolean; C: boolean } => {
      const w = { dotI: Infinity, dotC: Infinity, refI, refC };
      const yy = rk4(ctx, y, u, w);
      return { y: yy, I: watchI && !(w.dotI > COS_MAX_TURN), C: watchC && !(w.dotC > COS_MAX_TURN) };
    };
    let trial = step(h);
    let zI = false;
    let zC = false;
    if (trial.I || trial.C) {
      if (h > 1e-12 * dP) {
        h *= 0.5;
        continue;
      }
      // Still turning fast at a negligible step: the slip is at zero (if Newton steps below
      // bring it there) or passes too close to zero to resolve (the step is taken as it is).
      zI = trial.I;
      zC = trial.C;
      trial = { y, I: false, C: false };
    }
    const t = zI || zC ? 0 : h / dP;
    h = Math.min(dP, 2 * h);
    // Smooth events on [0, t]: cone excess of a stuck contact, vy = 0, work target.
    const at = (u: number): Vec => (u === 1 ? trial.y : rk4(ctx, y, u * t * dP, null));
    let frac = 1;
    let yEnd = trial.y;
    let leave = false;
    if ((ctx.stickI || ctx.stickC) && stickExcess(ctx, yEnd) > 0) {
      frac = bisect((u) => stickExcess(ctx, at(u)) > 0).hi;
      leave = true;
      zI = false;
      zC = false;
      yEnd = at(frac);
    }
    if (compressing && yEnd[1]! <= 0) {
      const u = bisect((v) => at(v * frac)[1]! <= 0).hi * frac;
      const yc = at(u);
      const wc = yc[5]!;
      wEnd = wc - ee * ee * wc;
      compressing = false;
      const d = deriv(ctx, yc);
      if (ee === 0 || !(d[1]! < 0)) {
        y = yc;
        P += u * t * dP;
        return finish(!(d[1]! < 0) ? 'stalled' : 'restitution');
      }
      if (yEnd[5]! <= wEnd) {
        const v = bisect((q) => at(u + q * (frac - u))[5]! <= wEnd).hi;
        y = at(u + v * (frac - u));
        P += (u + v * (frac - u)) * t * dP;
        return finish('restitution');
      }
    } else if (!compressing) {
      if (yEnd[5]! <= wEnd) {
        const v = bisect((q) => at(q * frac)[5]! <= wEnd).hi;
        y = at(v * frac);
        P += v * frac * t * dP;
        return finish('restitution');
      }
      if (yEnd[1]! >= 0) {
        const v = bisect((q) => at(q * frac)[1]! >= 0).hi;
        y = at(v * frac);
        P += v * frac * t * dP;
        return finish('stalled');
      }
    }
    y = yEnd;
    P += frac * t * dP;
    if (leave) {
      // The stuck contact starts to slip opposite to the friction it needed.
      const { g, h } = frictions(ctx, y);
      const [sxI, syI, sxC, syC] = slips({ ...ctx, offI: [0, 0], offC: [0, 0] }, y);
      if (ctx.stickI) {
        ctx.stickI = false;
        ctx.slaveI = true;
        ctx.offI = [sxI, syI];
        ctx.dirI = unit(-g[0], -g[1], [1, 0], 0);
      } else {
        ctx.stickC = false;
        ctx.slaveC = true;
        ctx.offC = [sxC, syC];
        ctx.dirC = unit(-h[0], -h[1], [1, 0], 0);
      }
    } else {
      // A watched slip that fell to roundoff in this step is at zero.
      const e = slips(ctx, y);
      if (watchI && Math.hypot(e[0], e[1]) <= zeroTol) zI = true;
      if (watchC && Math.hypot(e[2], e[3]) <= zeroTol) zC = true;
    }
    if (!leave && (zI || zC)) {
      // Final approach: Newton steps on the slip speed down to roundoff.
      for (let k = 0; k < 40; k++) {
        const e = slips(ctx, y);
        const ex = zI ? e[0] : e[2];
        const ey = zI ? e[1] : e[3];
        const rho = Math.hypot(ex, ey);
        if (rho <= zeroTol) break;
        const { g, h } = frictions(ctx, y);
        const r = slipRates(ctx, y, g, h);
        const rate = (ex * (zI ? r[0] : r[2]) + ey * (zI ? r[1] : r[3])) / rho;
        if (!(rate < 0)) break;
        const d = rho / -rate;
        y = rk4(ctx, y, d, null);
        P += d;
      }
      const e = slips(ctx, y);
      const rho = zI ? Math.hypot(e[0], e[1]) : Math.hypot(e[2], e[3]);
      if (rho > 1e-10 * V) {
        // Not a zero after all: a near miss too close to resolve; take a minimal step past it.
        y = rk4(ctx, y, 1e-12 * dP, null);
        P += 1e-12 * dP;
        continue;
      }
      if (zeroEvent(zI, zC)) return finish('stalled');
    }
  }
  throw new Error('reference: no end');
}
