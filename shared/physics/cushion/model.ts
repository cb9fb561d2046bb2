// The equations of motion of a ball against a cushion, in the impulse (Mathavan, Jackson and
// Parkin 2010, Proc. IMechE C 224(9), eqs. 9-15; doi 10.1243/09544062JMES1964).
//
// Variables y = [vx, vy, Ox, Oy, Oz, W], O = R ω (m/s), W the work of the normal force at the
// cushion contact I per unit mass; independent variable p = P / M. The paper's eq. 14 becomes
//   dvx/dp = gx + hx                 dOx/dp = 5/2 (gy + hy)
//   dvy/dp = -c - s gy + hy          dOy/dp = 5/2 (s gx - hx)
//   dW/dp  = c vy                    dOz/dp = -5/2 c gx
// with s = sin θ, c = cos θ, g the friction at I per unit normal impulse in the basis (e_x, t),
// t = (0, -s, c), and h the friction at the table contact C per unit impulse at I. Sliding:
//   g = -μw u_I,   h = -μs A u_C,   A = s - c gy (the table's normal, clamped at 0: it never pulls)
// with u the unit slip directions. Slips (eqs. 12, 13) and their rates:
//   xI = vx + s Oy - c Oz   dxI/dp = 7/2 gx + (1 - 5/2 s) hx
//   yI = -s vy + Ox         dyI/dp = s c + (s² + 5/2) gy + (5/2 - s) hy
//   xC = vx - Oy            dxC/dp = (1 - 5/2 s) gx + 7/2 hx
//   yC = vy + Ox            dyC/dp = -c + (5/2 - s) gy + 7/2 hy
// A contact whose slip is zero rolls (eqs. 15a, 15b) while the friction that keeps both its rates
// at zero fits in its friction cone. Only + - * / and Math.sqrt.

import { illinois } from './control.ts';

export const SLIDE = 0;
export const STICK = 1;
export type ContactMode = typeof SLIDE | typeof STICK;

/**
 * The friction model with its per-impact constants and each contact's mode. Number fields start
 * at -0 or a fraction so that V8 keeps them as doubles.
 */
export class CushionModel {
  s = -0;
  c = -0;
  muW = -0;
  muS = -0;
  /** (2/7)(1 - 5/2 s), (2/7) c, (2/7)(5/2 - s): the rolling-condition coefficients. */
  q1 = -0;
  q2 = -0;
  q3 = -0;
  modeI: ContactMode = SLIDE;
  modeC: ContactMode = SLIDE;
  /** Slip left when a contact was declared stuck; a slipping contact's direction is (slip - offset). */
  offIx = -0;
  offIy = -0;
  offCx = -0;
  offCy = -0;
  /** Slaved (quasi-static) slip: the direction its rates enforce (the hint), not its own. */
  qsI = false;
  qsC = false;
  /** A slaved slip whose rates vanish along it: its direction is held, not re-solved. */
  frozenI = false;
  frozenC = false;
  /** Direction of a slaved contact, or of one whose slip is below epsSlip (its onset). */
  hintIx = 1.5;
  hintIy = -0;
  hintCx = 1.5;
  hintCy = -0;
  epsSlip = -0;
  /** Slip directions at the step's start, and the smallest slip component along them met in the step. */
  refIx = -0;
  refIy = -0;
  refCx = -0;
  refCy = -0;
  minDotI = -0;
  minDotC = -0;
  /** Inside a step: a slip past its zero keeps the step's starting direction (the step is then cut). */
  stepping = false;
  /** Frictions and table normal of the last evaluation. */
  gx = -0;
  gy = -0;
  hx = -0;
  hy = -0;
  nC = -0;
  /** Output of direction() and onsetDirection(). */
  ux = 1.5;
  uy = -0;

  setConstants(s: number, c: number, muW: number, muS: number): void {
    this.s = s;
    this.c = c;
    this.muW = muW;
    this.muS = muS;
    this.q1 = (2 / 7) * (1 - 2.5 * s);
    this.q2 = (2 / 7) * c;
    this.q3 = (2 / 7) * (2.5 - s);
    this.modeI = this.modeC = SLIDE;
    this.offIx = this.offIy = this.offCx = this.offCy = 0;
    this.hintIx = this.hintCx = 1;
    this.hintIy = this.hintCy = 0;
    this.qsI = this.qsC = this.frozenI = this.frozenC = false;
  }

  /** Effective slips (slip minus offset) at y, and their rates from a derivative k. */
  slipIx(y: Float64Array): number { return y[0]! + this.s * y[3]! - this.c * y[4]! - this.offIx; }
  slipIy(y: Float64Array): number { return -this.s * y[1]! + y[2]! - this.offIy; }
  slipCx(y: Float64Array): number { return y[0]! - y[3]! - this.offCx; }
  slipCy(y: Float64Array): number { return y[1]! + y[2]! - this.offCy; }
  rateIx(k: Float64Array): number { return k[0]! + this.s * k[3]! - this.c * k[4]!; }
  rateIy(k: Float64Array): number { return -this.s * k[1]! + k[2]!; }
  rateCx(k: Float64Array): number { return k[0]! - k[3]!; }
  rateCy(k: Float64Array): number { return k[1]! + k[2]!; }

  /** Frictions g, h and the table normal nC at state (vx, vy, Ox, Oy, Oz) in the current modes. */
  friction(vx: number, vy: number, ox: number, oy: number, oz: number): void {
    const s = this.s;
    const c = this.c;
    let gx: number;
    let gy: number;
    let hx: number;
    let hy: number;
    let n: number;
    if (this.modeI === SLIDE) {
      if (this.qsI) {
        if (!this.frozenI && (!this.qsC || this.modeC === STICK)) {
          // Slaved: the direction I's rates enforce at this very state.
          this.affineAt(vx, vy, ox, oy);
          this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, true);
          this.hintIx = this.ux;
          this.hintIy = this.uy;
        }
        gx = -this.muW * this.hintIx;
        gy = -this.muW * this.hintIy;
      } else {
        this.direction(0, vx + s * oy - c * oz - this.offIx, -s * vy + ox - this.offIy);
        gx = -this.muW * this.ux;
        gy = -this.muW * this.uy;
      }
      n = s - c * gy;
      if (n < 0) n = 0;
      if (this.modeC === SLIDE) {
        const m = this.muS * n;
        if (this.qsC) {
          // Slaved while I slips: along C's rates without its own friction (isotropic in h).
          const ax = (1 - 2.5 * s) * gx;
          const ay = -c + (2.5 - s) * gy;
          const an = Math.sqrt(ax * ax + ay * ay);
          if (an > 0 && !this.frozenC) {
            this.hintCx = ax / an;
            this.hintCy = ay / an;
          }
          hx = -m * this.hintCx;
          hy = -m * this.hintCy;
        } else {
          this.direction(1, vx - oy - this.offCx, vy + ox - this.offCy);
          hx = -m * this.ux;
          hy = -m * this.uy;
        }
      } else {
        // C rolls (eq. 15b): dxC/dp = dyC/dp = 0.
        hx = -this.q1 * gx;
        hy = this.q2 - this.q3 * gy;
      }
    } else if (this.modeC === SLIDE) {
      // I rolls (eq. 15a), C slips: dxI/dp = dyI/dp = 0 with h = -μs (s - c gy) u_C.
      if (this.qsC) {
        this.ux = this.hintCx;
        this.uy = this.hintCy;
      } else {
        this.direction(1, vx - oy - this.offCx, vy + ox - this.offCy);
      }
      const fx = this.ux;
      const fy = this.uy;
      const k = (2.5 - s) * this.muS * fy;
      // (den > 0 whenever this branch is feasible: checked on entry, see stickMargin.)
      gy = (k * s - s * c) / (s * s + 2.5 + k * c);
      n = s - c * gy;
      const m = this.muS * n;
      hx = -m * fx;
      hy = -m * fy;
      gx = -this.q1 * hx;
    } else {
      // Both roll: g = (0, -c/(1+s)), h = (0, c/(1+s)), A = 1; every rate is zero.
      gx = 0;
      gy = -c / (1 + s);
      hx = 0;
      hy = c / (1 + s);
      n = 1;
    }
    this.gx = gx;
    this.gy = gy;
    this.hx = hx;
    this.hy = hy;
    this.nC = n;
  }

  /**
   * Unit direction of contact 0's (I) or 1's (C) slip (ex, ey) into (ux, uy), noting its
   * component along the step's starting direction (minDot). Below epsSlip the hint; inside a step,
   * past the zero or below epsSlip, the starting direction: the sliding equations continued, so
   * that a step aimed at the zero may land a hair beyond it (the solver cuts deeper crossings).
   */
  private direction(contact: number, ex: number, ey: number): void {
    const rx = contact === 0 ? this.refIx : this.refCx;
    const ry = contact === 0 ? this.refIy : this.refCy;
    const d = ex * rx + ey * ry;
    if (contact === 0) {
      if (d < this.minDotI) this.minDotI = d;
    } else if (d < this.minDotC) {
      this.minDotC = d;
    }
    const r = Math.sqrt(ex * ex + ey * ey);
    if (this.stepping && (d <= 0 || r <= this.epsSlip)) {
      this.ux = rx;
      this.uy = ry;
    } else if (r <= this.epsSlip) {
      this.ux = contact === 0 ? this.hintIx : this.hintCx;
      this.uy = contact === 0 ? this.hintIy : this.hintCy;
    } else {
      this.ux = ex / r;
      this.uy = ey / r;
    }
  }

  /** dy/dp at y, written into out (eq. 14 in the variables above). */
  derivative(y: Float64Array, out: Float64Array): void {
    const vy = y[1]!;
    this.friction(y[0]!, vy, y[2]!, y[3]!, y[4]!);
    const { gx, gy, hx, hy, s, c } = this;
    out[0] = gx + hx;
    out[1] = -c - s * gy + hy;
    out[2] = 2.5 * (gy + hy);
    out[3] = 2.5 * (s * gx - hx);
    out[4] = -2.5 * c * gx;
    out[5] = c * vy;
  }

  /**
   * How far the stuck contacts are from leaving their friction cones at y: the largest
   * |friction| - μ × normal (per unit impulse at I) over stuck contacts; > 0: one must slip.
   * -1 when none is stuck.
   */
  stickMargin(y: Float64Array): number {
    if (this.modeI === SLIDE && this.modeC === SLIDE) return -1;
    const saveI = this.minDotI;
    const saveC = this.minDotC;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    this.minDotI = saveI;
    this.minDotC = saveC;
    let margin = -1;
    if (this.modeI === STICK) {
      if (this.modeC === SLIDE && !(this.nC > 0)) return 1; // the rolling branch has no solution
      margin = Math.sqrt(this.gx * this.gx + this.gy * this.gy) - this.muW;
    }
    if (this.modeC === STICK) {
      const m = Math.sqrt(this.hx * this.hx + this.hy * this.hy) - this.muS * (this.nC > 0 ? this.nC : 0);
      if (m > margin) margin = m;
    }
    return margin;
  }

  /**
   * C's slip is zero and I slips: does C roll (true)? If not, its slip starts opposite to the
   * friction rolling would need (its rates are isotropic in h, so that is the exact onset).
   */
  onsetC(y: Float64Array): boolean {
    this.modeC = STICK;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    const { hx, hy } = this;
    const norm = Math.sqrt(hx * hx + hy * hy);
    this.qsC = false;
    this.frozenC = false;
    if (norm <= this.muS * (this.nC > 0 ? this.nC : 0)) return true;
    this.modeC = SLIDE;
    this.qsC = true;
    this.hintCx = -hx / norm;
    this.hintCy = -hy / norm;
    return false;
  }

  /**
   * I's slip is zero and C slips: does I roll (true)? If not, its slip starts along the u that
   * solves (λ + μw B) u = a, |u| = 1, λ >= 0, with a + B g I's rates as a function of g.
   */
  onsetI(y: Float64Array): boolean {
    this.modeI = STICK;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    this.qsI = false;
    this.frozenI = false;
    // (The rolling branch exists only while its denominator is positive, i.e. nC > 0.)
    if (this.nC > 0 && this.gx * this.gx + this.gy * this.gy <= this.muW * this.muW) return true;
    this.modeI = SLIDE;
    this.qsI = true;
    this.affineAt(y[0]!, y[1]!, y[2]!, y[3]!);
    this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, false);
    this.hintIx = this.ux;
    this.hintIy = this.uy;
    return false;
  }

  /** I's slip rates as a + B g (affineAt), g its friction per unit impulse, B = [[b11, b12], [0, b22]]. */
  private ax = -0;
  private ay = -0;
  private b11 = -0;
  private b12 = -0;
  private b22 = -0;

  /**
   * I's slip rates as an affine function of its friction g, the rest frozen. C rolling (eq. 15b
   * gives h): a = (0, 5/7 (1+s) c). C slipping: h = -μs (s - c gy) u_C in the rates above.
   */
  private affineAt(vx: number, vy: number, ox: number, oy: number): void {
    const s = this.s;
    const c = this.c;
    if (this.modeC === STICK) {
      this.ax = 0;
      this.ay = (5 / 7) * (1 + s) * c;
      this.b11 = 3.5 - (2 / 7) * (1 - 2.5 * s) * (1 - 2.5 * s);
      this.b12 = 0;
      this.b22 = s * s + 2.5 - (2 / 7) * (2.5 - s) * (2.5 - s);
      return;
    }
    let fx = this.hintCx;
    let fy = this.hintCy;
    if (!this.qsC) {
      const ex = vx - oy - this.offCx;
      const ey = vy + ox - this.offCy;
      const rc = Math.sqrt(ex * ex + ey * ey);
      if (rc > this.epsSlip) {
        fx = ex / rc;
        fy = ey / rc;
      }
    }
    const ms = this.muS;
    this.ax = -(1 - 2.5 * s) * ms * s * fx;
    this.ay = s * c - (2.5 - s) * ms * s * fy;
    this.b11 = 3.5;
    this.b12 = (1 - 2.5 * s) * ms * c * fx;
    this.b22 = s * s + 2.5 + (2.5 - s) * ms * c * fy;
  }

  /**
   * The direction I's slip would keep if slaved to its rates: u with (λ + μw B) u = a, |u| = 1,
   * λ of either sign (λ < 0: the slip shrinks along u). Leaves u in (ux, uy) and returns λ.
   */
  slavedI(y: Float64Array): number {
    this.affineAt(y[0]!, y[1]!, y[2]!, y[3]!);
    return this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, true);
  }

  /**
   * As slavedI for C while I slips: C's rates are a + 7/2 h, h = -μs N u, isotropic, so
   * u = a / |a| and λ = |a| - 7/2 μs N. NaN when there is no such direction.
   */
  slavedC(y: Float64Array): number {
    if (this.modeI === STICK) return this.slavedCRolling(y);
    const s = this.s;
    const c = this.c;
    let ex = this.hintIx;
    let ey = this.hintIy;
    if (!this.qsI) {
      const x = this.slipIx(y);
      const z = this.slipIy(y);
      const r = Math.sqrt(x * x + z * z);
      if (r > this.epsSlip) {
        ex = x / r;
        ey = z / r;
      }
    }
    const gx = -this.muW * ex;
    const gy = -this.muW * ey;
    let n = s - c * gy;
    if (n < 0) n = 0;
    const ax = (1 - 2.5 * s) * gx;
    const ay = -c + (2.5 - s) * gy;
    const an = Math.sqrt(ax * ax + ay * ay);
    if (!(an > 0)) return NaN;
    this.ux = ax / an;
    this.uy = ay / an;
    return an - 3.5 * this.muS * n;
  }

  /**
   * slavedC while I rolls (eq. 15a): C's rates are not isotropic then, but a slip along ±y stays
   * along ±y (h_x = 0 gives g_x = 0 and both x rates vanish). So a slip along y within 1e-3 rad
   * is slaved to it, with the rate from the rolling conditions; NaN otherwise.
   */
  private slavedCRolling(y: Float64Array): number {
    const ex = this.slipCx(y);
    const ey = this.slipCy(y);
    if (!(Math.abs(ex) <= 1e-3 * Math.abs(ey))) return NaN;
    const s = this.s;
    const c = this.c;
    const fy = ey > 0 ? 1 : -1;
    const k = (2.5 - s) * this.muS * fy;
    const den = s * s + 2.5 + k * c;
    if (!(den > 0)) return NaN;
    const gy = (k * s - s * c) / den;
    const n = s - c * gy;
    if (!(n > 0)) return NaN;
    this.ux = 0;
    this.uy = fy;
    return fy * (-c + (2.5 - s) * gy - 3.5 * this.muS * n * fy);
  }

  /**
   * Both slips are zero (which needs vy = 0). Both roll if the rolling frictions c/(1+s) fit in
   * both cones: true, nothing changes any more. Else, in this order, whichever is consistent:
   * C rolls and I slips (its onset with C rolling); I rolls and C slips along -y (opposite to the
   * friction both-rolling would need); both slip, I along +t and C along -y (an approximation,
   * docs/cushion.md, Limits).
   */
  onsetBoth(y: Float64Array): boolean {
    const s = this.s;
    const c = this.c;
    const f = c / (1 + s);
    // (A rolling contact is never slaved.)
    this.qsI = this.qsC = this.frozenI = this.frozenC = false;
    if (f <= this.muW && f <= this.muS) {
      this.modeI = STICK;
      this.modeC = STICK;
      return true;
    }
    const k1 = 3.5 - (2 / 7) * (1 - 2.5 * s) * (1 - 2.5 * s);
    const k3 = s * s + 2.5 - (2 / 7) * (2.5 - s) * (2.5 - s);
    this.onsetDirection(0, (5 / 7) * (1 + s) * c, k1, 0, k3, false);
    const gx = -this.muW * this.ux;
    const gy = -this.muW * this.uy;
    const hx = -this.q1 * gx;
    const hy = this.q2 - this.q3 * gy;
    let n = s - c * gy;
    if (n < 0) n = 0;
    this.modeI = SLIDE;
    this.hintIx = this.ux;
    this.hintIy = this.uy;
    if (hx * hx + hy * hy <= this.muS * n * (this.muS * n)) {
      this.modeC = STICK;
      return false;
    }
    this.modeI = STICK;
    this.modeC = SLIDE;
    this.qsC = true;
    this.hintCx = 0;
    this.hintCy = -1;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    if (this.nC > 0 && this.gx * this.gx + this.gy * this.gy <= this.muW * this.muW) return false;
    this.qsC = false;
    this.modeI = SLIDE;
    this.hintIx = 0;
    this.hintIy = 1;
    return false;
  }

  /**
   * The unit u with (λ I + μw B) u = a, B = [[b11, b12], [0, b22]]: the direction of a slip
   * whose rates a + B g, g = -μw u, point along it (rate λ u). With `anySign` false λ >= 0 (a
   * slip leaving zero); otherwise the root above both poles, by regula falsi on |u(λ)| = 1.
   * Leaves u in (ux, uy), returns λ.
   */
  private onsetDirection(ax: number, ay: number, b11: number, b12: number, b22: number, anySign: boolean): number {
    const mu = this.muW;
    const an = Math.sqrt(ax * ax + ay * ay);
    if (!(an > 0)) {
      this.ux = 1;
      this.uy = 0;
      return 0;
    }
    // Lowest λ at which both diagonal entries are positive.
    let lo = anySign ? -Infinity : 0;
    if (-mu * b11 > lo) lo = -mu * b11;
    if (-mu * b22 > lo) lo = -mu * b22;
    if (lo === -Infinity) lo = -an;
    let hi = (lo > 0 ? lo : 0) + an + mu * Math.abs(b12);
    for (let i = 0; i < 200 && this.uNorm2(hi, ax, ay, b11, b12, b22) > 1; i++) hi = 2 * hi + an;
    // No root above lo (a slip that would shrink although λ >= 0 was asked): λ = lo.
    if (!(this.uNorm2(lo, ax, ay, b11, b12, b22) > 1)) hi = lo;
    // g = 1 - 1/|u(λ)|, decreasing: > 0 below the root.
    const g = (lam: number): number => 1 - 1 / Math.sqrt(this.uNorm2(lam, ax, ay, b11, b12, b22));
    if (hi > lo) hi = illinois(g, lo, hi, g(lo), g(hi), 1e-13, 1e-13 * an);
    this.uNorm2(hi, ax, ay, b11, b12, b22);
    const un = Math.sqrt(this.ux * this.ux + this.uy * this.uy);
    if (un > 0) {
      this.ux /= un;
      this.uy /= un;
    } else {
      this.ux = ax / an;
      this.uy = ay / an;
    }
    return hi;
  }

  /** |u(λ)|², u(λ) = (λ + μw B)⁻¹ a into (ux, uy); Infinity at a pole (where it would be NaN). */
  private uNorm2(lam: number, ax: number, ay: number, b11: number, b12: number, b22: number): number {
    const mu = this.muW;
    const uy = ay / (lam + mu * b22);
    const ux = (ax - mu * b12 * uy) / (lam + mu * b11);
    this.ux = ux;
    this.uy = uy;
    const n2 = ux * ux + uy * uy;
    return n2 === n2 ? n2 : Infinity;
  }
}
