// The equations of motion of a ball against a cushion, integrated in the impulse
// (Mathavan, Jackson and Parkin 2010, "A theoretical analysis of billiard ball dynamics under
// cushion impacts", Proc. IMechE C 224(9), eqs. 9-15; doi 10.1243/09544062JMES1964).
//
// Internal variables, chosen so that every quantity is a speed:
//   y = [vx, vy, Ox, Oy, Oz, W] with O = R ω (m/s) and W the work of the normal force at the
//   cushion contact I per unit mass (J/kg); the independent variable is p = P / M (m/s).
// With q = 1/M these turn the paper's eq. 14 into
//   dvx/dp = gx + hx                 dOx/dp = 5/2 (gy + hy)
//   dvy/dp = -cosθ - sinθ gy + hy    dOy/dp = 5/2 (sinθ gx - hx)
//   dW/dp  = cosθ vy                 dOz/dp = -5/2 cosθ gx
// where (gx, gy) is the friction at I per unit normal impulse, in the tangent basis
// (e_x, t) with t = (0, -sinθ, cosθ), and (hx, hy) the friction at the table contact C per unit
// impulse at I. While both contacts slip (the paper's eq. 14):
//   g = -μw (cos φ, sin φ),   h = -μs A (cos φ', sin φ'),   A = sinθ - cosθ gy
// (A = sinθ + μw sinφ cosθ is the table's normal impulse per unit impulse at I; the table pushes
// and never pulls, so A is clamped at 0, a case the paper's constants never reach).
//
// Slip velocities (paper eqs. 12, 13):
//   xI = vx + sinθ Oy - cosθ Oz    yI = -sinθ vy + Ox
//   xC = vx - Oy                   yC = vy + Ox
// whose rates follow from the equations above:
//   dxI/dp = 7/2 gx + (1 - 5/2 sinθ) hx
//   dyI/dp = sinθ cosθ + (sin²θ + 5/2) gy + (5/2 - sinθ) hy
//   dxC/dp = (1 - 5/2 sinθ) gx + 7/2 hx
//   dyC/dp = -cosθ + (5/2 - sinθ) gy + 7/2 hy
// When a slip is zero the paper's rolling conditions (its eqs. 15a, 15b) hold: the friction of
// that contact is whatever keeps the slip zero, found by setting its two rates to zero, as long
// as it stays inside the friction cone. Only + - * / and Math.sqrt are used (cos φ = xI / s).

export const SLIDE = 0;
export const STICK = 1;
export type ContactMode = typeof SLIDE | typeof STICK;

/**
 * The friction model with its per-impact constants and the mode of each contact. One object is
 * reused across impacts; all scratch values are plain number fields (no allocation).
 */
// Number fields start at -0 (or a fraction), never at a small integer literal: V8 would give
// them a small-integer representation and deoptimize when the first fraction arrives.
export class CushionModel {
  /** sin θ, cos θ of the cushion contact (sin θ = (h - R) / R). */
  s = -0;
  c = -0;
  muW = -0;
  muS = -0;
  /** (2/7)(1 - 5/2 sinθ), (2/7) cosθ, (2/7)(5/2 - sinθ): the rolling-condition coefficients. */
  q1 = -0;
  q2 = -0;
  q3 = -0;

  modeI: ContactMode = SLIDE;
  modeC: ContactMode = SLIDE;
  /**
   * Slip left over when a contact was declared stuck (at most the event tolerance). The
   * direction of a slipping contact is taken from (slip - offset), so that after it leaves the
   * stick branch its direction grows from exactly zero.
   */
  offIx = -0;
  offIy = -0;
  offCx = -0;
  offCy = -0;
  /**
   * Quasi-static slip: the contact slips with the direction its rates enforce (the hint,
   * re-solved at every step by the solver) instead of the direction of its tiny slip vector,
   * whose dynamics are stiff near zero. Used from the onset of slip and in the last part of an
   * approach to zero (see CushionSolver).
   */
  qsI = false;
  qsC = false;
  /**
   * A slaved contact whose slip has stopped changing (its rates vanish along its direction, as
   * at the both-rolling threshold of friction): its direction is held, not re-solved.
   */
  frozenI = false;
  frozenC = false;
  /** Direction used while a slipping contact's (slip - offset) is below epsSlip (onset). */
  hintIx = 1.5;
  hintIy = -0;
  hintCx = 1.5;
  hintCy = -0;
  epsSlip = -0;

  /**
   * Unit slip directions at the step's start and the smallest stage components of the slips
   * along them, to detect a slip passing zero inside a step.
   */
  refIx = -0;
  refIy = -0;
  refCx = -0;
  refCy = -0;
  minDotI = -0;
  minDotC = -0;
  /** True only inside an integration step: enables the continuation past a zero slip. */
  stepping = false;

  /** Frictions and table normal of the last evaluation. */
  gx = -0;
  gy = -0;
  hx = -0;
  hy = -0;
  nC = -0;

  setConstants(s: number, c: number, muW: number, muS: number): void {
    this.s = s;
    this.c = c;
    this.muW = muW;
    this.muS = muS;
    this.q1 = (2 / 7) * (1 - 2.5 * s);
    this.q2 = (2 / 7) * c;
    this.q3 = (2 / 7) * (2.5 - s);
    this.modeI = SLIDE;
    this.modeC = SLIDE;
    this.offIx = 0;
    this.offIy = 0;
    this.offCx = 0;
    this.offCy = 0;
    this.hintIx = 1;
    this.hintIy = 0;
    this.hintCx = 1;
    this.hintCy = 0;
    this.qsI = false;
    this.qsC = false;
    this.frozenI = false;
    this.frozenC = false;
  }

  /** Effective slip at I (slip minus offset). */
  slipIx(y: Float64Array): number {
    return y[0]! + this.s * y[3]! - this.c * y[4]! - this.offIx;
  }
  slipIy(y: Float64Array): number {
    return -this.s * y[1]! + y[2]! - this.offIy;
  }
  slipCx(y: Float64Array): number {
    return y[0]! - y[3]! - this.offCx;
  }
  slipCy(y: Float64Array): number {
    return y[1]! + y[2]! - this.offCy;
  }
  /** Rates of the slips from a derivative vector k (linear in k). */
  rateIx(k: Float64Array): number {
    return k[0]! + this.s * k[3]! - this.c * k[4]!;
  }
  rateIy(k: Float64Array): number {
    return -this.s * k[1]! + k[2]!;
  }
  rateCx(k: Float64Array): number {
    return k[0]! - k[3]!;
  }
  rateCy(k: Float64Array): number {
    return k[1]! + k[2]!;
  }

  /**
   * Frictions g, h and table normal nC at state (vx, vy, Ox, Oy, Oz) in the current modes.
   * Also records, for a slipping contact, the dot product of its slip with the reference
   * direction (a negative value means the slip went through zero inside a step).
   */
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
        this.directionI(vx + s * oy - c * oz - this.offIx, -s * vy + ox - this.offIy);
        gx = -this.muW * this.ux;
        gy = -this.muW * this.uy;
      }
      n = s - c * gy;
      if (n < 0) n = 0;
      if (this.modeC === SLIDE) {
        const m = this.muS * n;
        if (this.qsC) {
          // Slaved: along C's rates without its own friction (isotropic in h).
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
          this.directionC(vx - oy - this.offCx, vy + ox - this.offCy);
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
        this.directionC(vx - oy - this.offCx, vy + ox - this.offCy);
      }
      const fx = this.ux;
      const fy = this.uy;
      const k = (2.5 - s) * this.muS * fy;
      // den > 0 whenever this branch is feasible (checked on entry, see stickMargin).
      const den = s * s + 2.5 + k * c;
      gy = (k * s - s * c) / den;
      n = s - c * gy;
      const m = this.muS * n;
      hx = -m * fx;
      hy = -m * fy;
      gx = -this.q1 * hx;
    } else {
      // Both roll: the rolling conditions give g = (0, -c/(1+s)), h = (0, c/(1+s)), A = 1,
      // and every rate is zero (this only happens with vy = 0; the solver ends there).
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
   * Unit slip direction of I into (ux, uy). Below epsSlip the onset hint; where the slip has
   * gone through zero inside a step (no longer along the step's starting direction) the
   * starting direction: the sliding equations continued smoothly, so that a step aimed at the
   * zero may land a hair beyond it (the solver rejects deeper crossings).
   */
  private directionI(ex: number, ey: number): void {
    const d = ex * this.refIx + ey * this.refIy;
    if (d < this.minDotI) this.minDotI = d;
    const r = Math.sqrt(ex * ex + ey * ey);
    if (this.stepping && (d <= 0 || r <= this.epsSlip)) {
      // (At the onset of slip the step's starting direction is the hint.)
      this.ux = this.refIx;
      this.uy = this.refIy;
    } else if (r <= this.epsSlip) {
      this.ux = this.hintIx;
      this.uy = this.hintIy;
    } else {
      const ir = 1 / r;
      this.ux = ex * ir;
      this.uy = ey * ir;
    }
  }

  /** As directionI, for C. */
  private directionC(ex: number, ey: number): void {
    const d = ex * this.refCx + ey * this.refCy;
    if (d < this.minDotC) this.minDotC = d;
    const r = Math.sqrt(ex * ex + ey * ey);
    if (this.stepping && (d <= 0 || r <= this.epsSlip)) {
      // (At the onset of slip the step's starting direction is the hint.)
      this.ux = this.refCx;
      this.uy = this.refCy;
    } else if (r <= this.epsSlip) {
      this.ux = this.hintCx;
      this.uy = this.hintCy;
    } else {
      const ir = 1 / r;
      this.ux = ex * ir;
      this.uy = ey * ir;
    }
  }

  /**
   * Which branch evalFast handles in the current modes: 0 both slip, 1 I slips and C rolls,
   * 2 I rolls and C slips (none slaved); -1 otherwise (use derivative()).
   */
  fastMode(): number {
    if (this.modeI === SLIDE) {
      if (this.qsI) return -1;
      if (this.modeC === SLIDE) return this.qsC ? -1 : 0;
      return 1;
    }
    if (this.modeC === SLIDE && !this.qsC) return 2;
    return -1;
  }

  /** Output of evalFast: dy/dp. */
  d0 = -0;
  d1 = -0;
  d2 = -0;
  d3 = -0;
  d4 = -0;
  d5 = -0;

  /**
   * derivative() inside a step for the branches of fastMode() (mode >= 0), on scalars, with
   * the same operations in the same order (so the same bits). Fills d0..d5.
   */
  evalFast(mode: number, vx: number, vy: number, ox: number, oy: number, oz: number): void {
    const s = this.s;
    const c = this.c;
    let gx: number;
    let gy: number;
    let hx: number;
    let hy: number;
    if (mode !== 2) {
      const ex = vx + s * oy - c * oz - this.offIx;
      const ey = -s * vy + ox - this.offIy;
      const d = ex * this.refIx + ey * this.refIy;
      if (d < this.minDotI) this.minDotI = d;
      const r = Math.sqrt(ex * ex + ey * ey);
      let ux: number;
      let uy: number;
      if (d <= 0 || r <= this.epsSlip) {
        ux = this.refIx;
        uy = this.refIy;
      } else {
        const ir = 1 / r;
        ux = ex * ir;
        uy = ey * ir;
      }
      gx = -this.muW * ux;
      gy = -this.muW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      if (mode === 0) {
        const m = this.muS * n;
        const fx = vx - oy - this.offCx;
        const fy = vy + ox - this.offCy;
        const dc = fx * this.refCx + fy * this.refCy;
        if (dc < this.minDotC) this.minDotC = dc;
        const rc = Math.sqrt(fx * fx + fy * fy);
        if (dc <= 0 || rc <= this.epsSlip) {
          ux = this.refCx;
          uy = this.refCy;
        } else {
          const irc = 1 / rc;
          ux = fx * irc;
          uy = fy * irc;
        }
        hx = -m * ux;
        hy = -m * uy;
      } else {
        hx = -this.q1 * gx;
        hy = this.q2 - this.q3 * gy;
      }
    } else {
      const fx0 = vx - oy - this.offCx;
      const fy0 = vy + ox - this.offCy;
      const dc = fx0 * this.refCx + fy0 * this.refCy;
      if (dc < this.minDotC) this.minDotC = dc;
      const rc = Math.sqrt(fx0 * fx0 + fy0 * fy0);
      let fx: number;
      let fy: number;
      if (dc <= 0 || rc <= this.epsSlip) {
        fx = this.refCx;
        fy = this.refCy;
      } else {
        const irc = 1 / rc;
        fx = fx0 * irc;
        fy = fy0 * irc;
      }
      const k = (2.5 - s) * this.muS * fy;
      const den = s * s + 2.5 + k * c;
      gy = (k * s - s * c) / den;
      const n = s - c * gy;
      const m = this.muS * n;
      hx = -m * fx;
      hy = -m * fy;
      gx = -this.q1 * hx;
    }
    this.d0 = gx + hx;
    this.d1 = -c - s * gy + hy;
    this.d2 = 2.5 * (gy + hy);
    this.d3 = 2.5 * (s * gx - hx);
    this.d4 = -2.5 * c * gx;
    this.d5 = c * vy;
  }

  /** dy/dp at y, written into out. */
  derivative(y: Float64Array, out: Float64Array): void {
    const vy = y[1]!;
    this.friction(y[0]!, vy, y[2]!, y[3]!, y[4]!);
    const gx = this.gx;
    const gy = this.gy;
    const hx = this.hx;
    const hy = this.hy;
    const s = this.s;
    const c = this.c;
    out[0] = gx + hx;
    out[1] = -c - s * gy + hy;
    out[2] = 2.5 * (gy + hy);
    out[3] = 2.5 * (s * gx - hx);
    out[4] = -2.5 * c * gx;
    out[5] = c * vy;
  }

  /**
   * How far the stuck contacts are from leaving the friction cone at y: max over stuck
   * contacts of |friction| - μ × normal (per unit impulse at I). Positive means a stuck
   * contact cannot stay stuck. Returns -1 when no contact is stuck.
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
      const n = this.nC > 0 ? this.nC : 0;
      const m = Math.sqrt(this.hx * this.hx + this.hy * this.hy) - this.muS * n;
      if (m > margin) margin = m;
    }
    return margin;
  }

  /**
   * Contact C's slip is zero and I slips (direction from y, or I's hint): does C roll (true)? If not,
   * its slip starts opposite to the friction rolling would need (its slip rates are isotropic
   * in h, so that is the exact onset direction), stored as C's hint.
   */
  onsetC(y: Float64Array): boolean {
    this.modeC = STICK;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    const hx = this.hx;
    const hy = this.hy;
    const n = this.nC > 0 ? this.nC : 0;
    const norm = Math.sqrt(hx * hx + hy * hy);
    this.qsC = false;
    this.frozenC = false;
    if (norm <= this.muS * n) return true;
    this.modeC = SLIDE;
    this.qsC = true;
    this.hintCx = -hx / norm;
    this.hintCy = -hy / norm;
    return false;
  }

  /**
   * Contact I's slip is zero and C slips (direction from y, or C's hint): does I roll (true)? If not,
   * the direction u in which its slip starts solves (λ + μw B) u = a, |u| = 1, λ >= 0, where
   * a + B g are I's slip rates as an affine function of its friction g (see onsetDirection).
   */
  onsetI(y: Float64Array): boolean {
    const s = this.s;
    const c = this.c;
    this.modeI = STICK;
    this.friction(y[0]!, y[1]!, y[2]!, y[3]!, y[4]!);
    // The rolling branch exists only while its denominator is positive, i.e. nC > 0.
    this.qsI = false;
    this.frozenI = false;
    if (this.nC > 0 && this.gx * this.gx + this.gy * this.gy <= this.muW * this.muW) return true;
    this.modeI = SLIDE;
    this.qsI = true;
    this.affineI(y);
    this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, false);
    this.hintIx = this.ux;
    this.hintIy = this.uy;
    return false;
  }

  /** I's slip rates as a + B g (filled by affineI), g its friction per unit impulse. */
  private ax = -0;
  private ay = -0;
  private b11 = -0;
  private b12 = -0;
  private b22 = -0;

  /**
   * I's slip rates as an affine function of its friction g at y, the rest frozen. With C
   * slipping: dxI/dp = 7/2 gx + (1 - 5/2 s) hx, dyI/dp = s c + (s² + 5/2) gy + (5/2 - s) hy,
   * h = -μs (s - c gy) u_C. With C rolling (h from eq. 15b):
   * dxI/dp = K1 gx, dyI/dp = 5/7 (1+s) c + K3 gy.
   */
  private affineI(y: Float64Array): void {
    this.affineAt(y[0]!, y[1]!, y[2]!, y[3]!);
  }

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
    let fx: number;
    let fy: number;
    if (this.qsC) {
      fx = this.hintCx;
      fy = this.hintCy;
    } else {
      fx = vx - oy - this.offCx;
      fy = vy + ox - this.offCy;
      const rc = Math.sqrt(fx * fx + fy * fy);
      if (rc > this.epsSlip) {
        fx /= rc;
        fy /= rc;
      } else {
        fx = this.hintCx;
        fy = this.hintCy;
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
   * The direction I's slip would keep if it were slaved to its rates (the quasi-static slip):
   * u with (λ + μw B) u = a, |u| = 1, λ of either sign (λ < 0: the slip shrinks along u).
   * Leaves u in (ux, uy) and returns λ, the rate of the slip speed.
   */
  slavedI(y: Float64Array): number {
    this.affineI(y);
    return this.onsetDirection(this.ax, this.ay, this.b11, this.b12, this.b22, true);
  }

  /**
   * As slavedI for C while I slips: C's rates are a + 7/2 h with h = -μs N u, isotropic, so
   * u = a / |a| and λ = |a| - 7/2 μs N. NaN when I rolls (then C's rates are not of this form).
   */
  slavedC(y: Float64Array): number {
    if (this.modeI === STICK) return this.slavedCRolling(y);
    const s = this.s;
    const c = this.c;
    let gx: number;
    let gy: number;
    if (this.qsI) {
      gx = -this.muW * this.hintIx;
      gy = -this.muW * this.hintIy;
    } else {
      let ex = y[0]! + s * y[3]! - c * y[4]! - this.offIx;
      let ey = -s * y[1]! + y[2]! - this.offIy;
      const r = Math.sqrt(ex * ex + ey * ey);
      if (r > this.epsSlip) {
        ex /= r;
        ey /= r;
      } else {
        ex = this.hintIx;
        ey = this.hintIy;
      }
      gx = -this.muW * ex;
      gy = -this.muW * ey;
    }
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
   * slavedC while I rolls (eq. 15a). C's rates are then not isotropic in its friction, but a
   * slip along ±y stays along ±y: with u = (0, ±1), h_x = 0, so g_x = -q1 h_x = 0 and both x
   * rates vanish. So when C's slip lies along y (within 1e-3 rad) that is its slaved direction,
   * with rate λ = ±(-cosθ + (5/2 - sinθ) g_y + 7/2 h_y) from the rolling conditions (the same
   * formulas as friction()'s branch); NaN otherwise (no closed form: C follows its own
   * direction). Found on a creep with μw 1.3: C's slip shrank along -y at a rate proportional
   * to itself, and the relaxation limit allowed steps of a fraction of it, without end.
   */
  private slavedCRolling(y: Float64Array): number {
    const ex = y[0]! - y[3]! - this.offCx;
    const ey = y[1]! + y[2]! - this.offCy;
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
    const hy = -this.muS * n * fy;
    this.ux = 0;
    this.uy = fy;
    return fy * (-c + (2.5 - s) * gy + 3.5 * hy);
  }

  /**
   * Both slips are zero (which needs vy = 0) at state y. Both roll if the constant rolling
   * frictions c/(1+s) fit in both cones (then nothing changes any more: the solver ends).
   * Otherwise C rolls and I slips if that is consistent (I's onset from its rates with C
   * rolling: dxI/dp = K1 gx, dyI/dp = 5/7 (1+s) c + K3 gy); otherwise I rolls and C slips, opposite
   * to the friction both-rolling would need, if I's rolling friction with C slipping so fits in
   * I's cone; otherwise both slip, I upward and C downward along t and y, the directions opposite
   * to the frictions both-rolling would need (an approximation, documented in docs/cushion.md).
   * (Both slips reach zero together whenever the cushion contact rolls through the end of
   * compression of a head-on impact: the table slip is then (1 + s) vy.)
   */
  onsetBoth(y: Float64Array): boolean {
    const s = this.s;
    const c = this.c;
    const f = c / (1 + s);
    // A rolling contact is never slaved (a stale flag made slavedStart aim a rolling contact's
    // residual at zero again and again, with steps too small to move p).
    this.qsI = false;
    this.qsC = false;
    this.frozenI = false;
    this.frozenC = false;
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
    // I rolls and C slips along -y (opposite to the friction c/(1+s) along +y that it would need
    // to roll), slaved as it grows: consistent if I's rolling friction (eq. 15a with C slipping)
    // fits in I's cone.
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

  /** Output of onsetDirection. */
  ux = 1.5;
  uy = -0;

  /**
   * The unit vector u with (λ I + μw B) u = a, B = [[b11, b12], [0, b22]]: the direction of a
   * slip whose rates a + B g, with g = -μw u, point along it (rate λ u). With `anySign` false,
   * λ >= 0 (a slip leaving zero); otherwise the root with λ above both poles (a slip that may
   * also shrink). Bisection on λ, a fixed number of halvings, so it always ends. Leaves u in
   * (ux, uy) and returns λ. When μw = 0, u = a / |a|.
   */
  private onsetDirection(ax: number, ay: number, b11: number, b12: number, b22: number, anySign: boolean): number {
    const mu = this.muW;
    const an = Math.sqrt(ax * ax + ay * ay);
    if (!(an > 0)) {
      this.ux = 1;
      this.uy = 0;
      return 0;
    }
    // Lowest λ for which both diagonal entries are positive.
    let lo = anySign ? -Infinity : 0;
    if (-mu * b11 > lo) lo = -mu * b11;
    if (-mu * b22 > lo) lo = -mu * b22;
    if (lo === -Infinity) lo = -an;
    // Grow hi until |u(hi)| <= 1.
    let hi = (lo > 0 ? lo : 0) + an + mu * Math.abs(b12);
    for (let i = 0; i < 200 && this.uNorm2(hi, ax, ay, b11, b12, b22) > 1; i++) hi = 2 * hi + an;
    if (!(this.uNorm2(lo, ax, ay, b11, b12, b22) > 1)) {
      // No root above lo (a slip that would shrink although λ >= 0 was asked): λ = lo.
      hi = lo;
    }
    // Illinois regula falsi on f(λ) = 1 / |u(λ)| - 1, increasing, -1 at a pole, >= 0 at hi.
    let flo = 1 / Math.sqrt(this.uNorm2(lo, ax, ay, b11, b12, b22)) - 1;
    let fhi = 1 / Math.sqrt(this.uNorm2(hi, ax, ay, b11, b12, b22)) - 1;
    let side = 0;
    for (let i = 0; i < 100 && hi > lo && fhi > 0; i++) {
      let x = lo + (hi - lo) * (flo / (flo - fhi));
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      if (!(x > lo && x < hi)) break;
      const fx = 1 / Math.sqrt(this.uNorm2(x, ax, ay, b11, b12, b22)) - 1;
      if (fx < 0) {
        lo = x;
        flo = fx;
        if (side === 1) fhi *= 0.5;
        side = 1;
      } else {
        hi = x;
        fhi = fx;
        if (side === -1) flo *= 0.5;
        side = -1;
      }
      if (hi - lo <= 1e-13 * (Math.abs(hi) + an)) break;
    }
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

  private uNorm2(lam: number, ax: number, ay: number, b11: number, b12: number, b22: number): number {
    const mu = this.muW;
    const uy = ay / (lam + mu * b22);
    const ux = (ax - mu * b12 * uy) / (lam + mu * b11);
    this.ux = ux;
    this.uy = uy;
    const n2 = ux * ux + uy * uy;
    // At a pole |u| is infinite. Computed, it can come out NaN (b12 = 0 times an infinite uy,
    // or 0 / 0), which onsetDirection took for "no root above the pole" and returned the pole
    // as the slaved slip's rate: -0.91 where the slip shrank at -3.5e-4, so that every step was
    // aimed at a zero 2,600 times nearer than the slip's, until the step cap threw (friction a
    // hair below the both-rolling threshold, the table contact rolling; a regression test).
    return n2 === n2 ? n2 : Infinity;
  }
}
