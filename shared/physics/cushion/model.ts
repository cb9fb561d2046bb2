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
 * One contact's friction state: I, the ball on the cushion's nose, or C, the ball on the cloth.
 * Number fields start at -0 or a fraction so that V8 keeps them as doubles.
 */
export class Contact {
  mode: ContactMode = SLIDE;
  /** Slip left when the contact was declared rolling; a slipping contact's direction is (slip - offset). */
  offX = -0;
  offY = -0;
  /** Slaved (quasi-static) slip: it takes the direction its rates enforce (the hint), not its own. */
  slaved = false;
  /** A slaved slip whose rates vanish along it: its direction is held, not re-solved. */
  held = false;
  /** Direction of a slaved contact, or of one whose slip is below epsSlip (its onset). */
  hintX = 1.5;
  hintY = -0;
  /** Slip direction at the step's start, and the smallest slip component along it met in the step. */
  refX = -0;
  refY = -0;
  minDot = -0;
  /**
   * The slip as a function of the state (eqs. 12, 13): x = vx + ax Oy - bx Oz, y = ay vy + Ox.
   * I: ax = s, bx = c, ay = -s; C: ax = -1, bx = 0, ay = 1.
   */
  private ax = -0;
  private bx = -0;
  private ay = -0;
  /** The contact's friction coefficient: μw at I, μs at C. */
  mu = -0;

  reset(ax: number, bx: number, ay: number, mu: number): void {
    this.mu = mu;
    this.ax = ax;
    this.bx = bx;
    this.ay = ay;
    this.mode = SLIDE;
    this.offX = this.offY = 0;
    this.hintX = 1;
    this.hintY = 0;
    this.slaved = this.held = false;
  }

  /** The slip at y (eqs. 12, 13). */
  rawX(y: Float64Array): number { return y[0]! + this.ax * y[3]! - this.bx * y[4]!; }
  rawY(y: Float64Array): number { return this.ay * y[1]! + y[2]!; }

  /** Its slip at y becomes its offset: the slip is zero there (a rolling spell's start or end). */
  zeroAt(y: Float64Array): void {
    this.offX = this.rawX(y);
    this.offY = this.rawY(y);
  }

  /** The effective slip (slip minus offset) at y, and its rates from a derivative k. */
  slipX(y: Float64Array): number { return this.rawX(y) - this.offX; }
  slipY(y: Float64Array): number { return this.rawY(y) - this.offY; }
  rateX(k: Float64Array): number { return k[0]! + this.ax * k[3]! - this.bx * k[4]!; }
  rateY(k: Float64Array): number { return this.ay * k[1]! + k[2]!; }

  /** Sets the slaved and held flags and the hint. */
  slave(slaved: boolean, held: boolean, ux: number, uy: number): void {
    this.slaved = slaved;
    this.held = held;
    this.hintX = ux;
    this.hintY = uy;
  }
}

/** The friction model with its per-impact constants and its two contacts. */
export class CushionModel {
  s = -0;
  c = -0;
  muW = -0;
  muS = -0;
  /** (2/7)(1 - 5/2 s), (2/7) c, (2/7)(5/2 - s): eq. 15b's coefficients (rollingC). */
  q1 = -0;
  q2 = -0;
  q3 = -0;
  /** I's slip rates with C rolling, a + B g (eq. 15b in I's rates): a = (0, ra), B = diag(rb1, rb2). */
  ra = -0;
  rb1 = -0;
  rb2 = -0;
  /** The cushion contact I and the table contact C. */
  readonly I = new Contact();
  readonly C = new Contact();
  /** Both, I first: the order every loop over them keeps. */
  readonly contacts: readonly [Contact, Contact] = [this.I, this.C];
  epsSlip = -0;
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
    this.ra = (5 / 7) * (1 + s) * c;
    this.rb1 = 3.5 - (2 / 7) * (1 - 2.5 * s) * (1 - 2.5 * s);
    this.rb2 = s * s + 2.5 - (2 / 7) * (2.5 - s) * (2.5 - s);
    this.I.reset(s, c, -s, muW);
    this.C.reset(-1, 0, 1, muS);
  }

  /** The table's normal impulse per unit impulse at I, A = s - c gy, clamped at 0 (it never pulls). */
  private tableNormal(gy: number): number {
    const n = this.s - this.c * gy;
    return n < 0 ? 0 : n;
  }

  /** Eq. 15b: the friction at C that keeps C rolling, for the friction g at I, into (hx, hy). */
  private rollingC(gx: number, gy: number): void {
    this.hx = -this.q1 * gx;
    this.hy = this.q2 - this.q3 * gy;
  }

  /**
   * Eq. 15a with C slipping along (0, fy)'s y part: gy that keeps I rolling, with
   * h = -μs (s - c gy) u_C; the denominator is returned in `den` (the branch needs it positive).
   */
  private rollingIgy(fy: number): number {
    const s = this.s;
    const k = (2.5 - s) * this.muS * fy;
    this.den = s * s + 2.5 + k * this.c;
    return (k * s - s * this.c) / this.den;
  }

  private den = -0;

  /** C's slip rates without its own friction, (dxC/dp, dyC/dp) at h = 0 (its rates are that + 7/2 h), into (cax, cay). */
  private cRatesFree(gx: number, gy: number): void {
    this.cax = (1 - 2.5 * this.s) * gx;
    this.cay = -this.c + (2.5 - this.s) * gy;
  }

  private cax = -0;
  private cay = -0;

  /** Frictions g, h and the table normal nC at the state y in the current modes. */
  friction(y: Float64Array): void {
    const s = this.s;
    const c = this.c;
    let gx: number;
    let gy: number;
    let hx: number;
    let hy: number;
    let n: number;
    if (this.I.mode === SLIDE) {
      if (this.I.slaved) {
        if (!this.I.held && (!this.C.slaved || this.C.mode === STICK)) {
          // Slaved: the direction I's rates enforce at this very state.
          this.affineAt(y);
          this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, true);
          this.I.hintX = this.ux;
          this.I.hintY = this.uy;
        }
        gx = -this.muW * this.I.hintX;
        gy = -this.muW * this.I.hintY;
      } else {
        this.direction(this.I, this.I.slipX(y), this.I.slipY(y));
        gx = -this.muW * this.ux;
        gy = -this.muW * this.uy;
      }
      n = this.tableNormal(gy);
      if (this.C.mode === SLIDE) {
        const m = this.muS * n;
        if (this.C.slaved) {
          // Slaved while I slips: along C's rates without its own friction (isotropic in h).
          this.cRatesFree(gx, gy);
          const ax = this.cax;
          const ay = this.cay;
          const an = Math.sqrt(ax * ax + ay * ay);
          if (an > 0 && !this.C.held) {
            this.C.hintX = ax / an;
            this.C.hintY = ay / an;
          }
          hx = -m * this.C.hintX;
          hy = -m * this.C.hintY;
        } else {
          this.direction(this.C, this.C.slipX(y), this.C.slipY(y));
          hx = -m * this.ux;
          hy = -m * this.uy;
        }
      } else {
        // C rolls (eq. 15b): dxC/dp = dyC/dp = 0.
        this.rollingC(gx, gy);
        hx = this.hx;
        hy = this.hy;
      }
    } else if (this.C.mode === SLIDE) {
      // I rolls (eq. 15a), C slips: dxI/dp = dyI/dp = 0 with h = -μs (s - c gy) u_C.
      if (this.C.slaved) {
        this.ux = this.C.hintX;
        this.uy = this.C.hintY;
      } else {
        this.direction(this.C, this.C.slipX(y), this.C.slipY(y));
      }
      const fx = this.ux;
      const fy = this.uy;
      // (den > 0 whenever this branch is feasible: checked on entry, see stickMargin.)
      gy = this.rollingIgy(fy);
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
   * Unit direction of a contact's slip (ex, ey) into (ux, uy), noting its
   * component along the step's starting direction (minDot). Below epsSlip the hint; inside a step,
   * past the zero or below epsSlip, the starting direction: the sliding equations continued, so
   * that a step aimed at the zero may land a hair beyond it (the solver cuts deeper crossings).
   */
  private direction(ct: Contact, ex: number, ey: number): void {
    const rx = ct.refX;
    const ry = ct.refY;
    const d = ex * rx + ey * ry;
    if (d < ct.minDot) ct.minDot = d;
    const r = Math.sqrt(ex * ex + ey * ey);
    if (this.stepping && (d <= 0 || r <= this.epsSlip)) {
      this.ux = rx;
      this.uy = ry;
    } else if (r <= this.epsSlip) {
      this.ux = ct.hintX;
      this.uy = ct.hintY;
    } else {
      this.ux = ex / r;
      this.uy = ey / r;
    }
  }

  /** dy/dp at y, written into out (eq. 14 in the variables above). */
  derivative(y: Float64Array, out: Float64Array): void {
    const vy = y[1]!;
    this.friction(y);
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
    if (this.I.mode === SLIDE && this.C.mode === SLIDE) return -1;
    const saveI = this.I.minDot;
    const saveC = this.C.minDot;
    this.friction(y);
    this.I.minDot = saveI;
    this.C.minDot = saveC;
    let margin = -1;
    if (this.I.mode === STICK) {
      if (this.C.mode === SLIDE && !(this.nC > 0)) return 1; // the rolling branch has no solution
      margin = Math.sqrt(this.gx * this.gx + this.gy * this.gy) - this.muW;
    }
    if (this.C.mode === STICK) {
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
    this.C.mode = STICK;
    this.friction(y);
    const { hx, hy } = this;
    const norm = Math.sqrt(hx * hx + hy * hy);
    this.C.slaved = false;
    this.C.held = false;
    if (norm <= this.muS * (this.nC > 0 ? this.nC : 0)) return true;
    this.C.mode = SLIDE;
    this.C.slaved = true;
    this.C.hintX = -hx / norm;
    this.C.hintY = -hy / norm;
    return false;
  }

  /**
   * I's slip is zero and C slips: does I roll (true)? If not, its slip starts along the u that
   * solves (λ + μw B) u = a, |u| = 1, λ >= 0, with a + B g I's rates as a function of g.
   */
  onsetI(y: Float64Array): boolean {
    this.I.mode = STICK;
    this.friction(y);
    this.I.slaved = false;
    this.I.held = false;
    // (The rolling branch exists only while its denominator is positive, i.e. nC > 0.)
    if (this.nC > 0 && this.gx * this.gx + this.gy * this.gy <= this.muW * this.muW) return true;
    this.I.mode = SLIDE;
    this.I.slaved = true;
    this.affineAt(y);
    this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, false);
    this.I.hintX = this.ux;
    this.I.hintY = this.uy;
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
  private affineAt(y: Float64Array): void {
    const s = this.s;
    const c = this.c;
    if (this.C.mode === STICK) {
      this.ax = 0;
      this.ay = this.ra;
      this.b11 = this.rb1;
      this.b12 = 0;
      this.b22 = this.rb2;
      return;
    }
    let fx = this.C.hintX;
    let fy = this.C.hintY;
    if (!this.C.slaved) {
      const ex = this.C.slipX(y);
      const ey = this.C.slipY(y);
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
    this.affineAt(y);
    return this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, true);
  }

  /**
   * As slavedI for C while I slips: C's rates are a + 7/2 h, h = -μs N u, isotropic, so
   * u = a / |a| and λ = |a| - 7/2 μs N. NaN when there is no such direction.
   */
  slavedC(y: Float64Array): number {
    if (this.I.mode === STICK) return this.slavedCRolling(y);
    const s = this.s;
    const c = this.c;
    let ex = this.I.hintX;
    let ey = this.I.hintY;
    if (!this.I.slaved) {
      const x = this.I.slipX(y);
      const z = this.I.slipY(y);
      const r = Math.sqrt(x * x + z * z);
      if (r > this.epsSlip) {
        ex = x / r;
        ey = z / r;
      }
    }
    const gx = -this.muW * ex;
    const gy = -this.muW * ey;
    const n = this.tableNormal(gy);
    this.cRatesFree(gx, gy);
    const ax = this.cax;
    const ay = this.cay;
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
    const ex = this.C.slipX(y);
    const ey = this.C.slipY(y);
    if (!(Math.abs(ex) <= 1e-3 * Math.abs(ey))) return NaN;
    const s = this.s;
    const c = this.c;
    const fy = ey > 0 ? 1 : -1;
    const gy = this.rollingIgy(fy);
    if (!(this.den > 0)) return NaN;
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
    this.I.slaved = this.C.slaved = this.I.held = this.C.held = false;
    if (f <= this.muW && f <= this.muS) {
      this.I.mode = STICK;
      this.C.mode = STICK;
      return true;
    }
    this.onsetDirection(0, this.ra, this.rb1, 0, this.rb2, false);
    const gx = -this.muW * this.ux;
    const gy = -this.muW * this.uy;
    this.rollingC(gx, gy);
    const hx = this.hx;
    const hy = this.hy;
    const n = this.tableNormal(gy);
    this.I.mode = SLIDE;
    this.I.hintX = this.ux;
    this.I.hintY = this.uy;
    if (hx * hx + hy * hy <= this.muS * n * (this.muS * n)) {
      this.C.mode = STICK;
      return false;
    }
    this.I.mode = STICK;
    this.C.mode = SLIDE;
    this.C.slaved = true;
    this.C.hintX = 0;
    this.C.hintY = -1;
    this.friction(y);
    if (this.nC > 0 && this.gx * this.gx + this.gy * this.gy <= this.muW * this.muW) return false;
    this.C.slaved = false;
    this.I.mode = SLIDE;
    this.I.hintX = 0;
    this.I.hintY = 1;
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
