// One cushion impact, integrated in the impulse (Mathavan et al. 2010): compression until vy = 0
// (work W_c), restitution until the work done since reaches e_e² W_c. Between events the
// Dormand-Prince step (integrator.ts) with PI control (control.ts). The events:
//  - a sliding slip reaches zero: the step is aimed at it, then the rolling conditions (eqs.
//    15a/15b) decide whether the contact rolls or slips on in a new direction;
//  - a rolling contact needs more friction than μ × its normal: located on the continuous
//    extension, the contact starts to slip;
//  - vy = 0 (end of compression) and the work target (the end), located on the extension;
//  - the ball can recede no more before the target: 'stalled', ending with vy = 0.
// Only + - * / and Math.sqrt. MAX_STEPS throws: never a wrong answer.
import {
  approachFactor, errorMemory, EVENT_FRACTION, FIRST_MEMORY, HINT_FRACTION, illinois, invRoot, MAX_STEPS, nextStep,
  PIN_FRACTION, QS_EXIT, QS_FRACTION, QS_GROW, QS_HOLD_RHO, QS_RHO, RELAX_MAX, RESTART_FRACTION, TURN_MAX,
  ZERO_FRACTION, zeroDistance,
} from './control.ts';
import { DIM, Dopri5 } from './integrator.ts';
import { CushionModel, SLIDE, STICK, type Contact } from './model.ts';
import type { CushionOutcome } from './types.ts';

/** Stalls an impact may re-decide (redecideAtStall): a guard against trading modes. */
const REDECISIONS = 4;
/** At a stall, a sliding slip within this many event tolerances of zero is taken as zero. */
const STALL_ZERO = 100;

// What accept() found in a step.
const ENDED = 0, AGAIN = 1, LEFT_CONE = 2, ACCEPTED = 3;

/** One sample of the impact's history (figures, the lab, checks). */
export interface CushionTracePoint {
  /** Impulse at the cushion so far (N s). */
  readonly P: number;
  readonly vx: number; readonly vy: number; readonly wx: number; readonly wy: number; readonly wz: number;
  /** Slip velocities at I (cushion) and C (table), m/s. */
  readonly xI: number; readonly yI: number; readonly xC: number; readonly yC: number;
  /** Work of the normal force at I so far (J); falls during restitution. */
  readonly W: number;
  readonly stickI: boolean;
  readonly stickC: boolean;
}

export class CushionSolver {
  readonly model = new CushionModel();
  private readonly rk = new Dopri5();
  /** The state, then the result: [vx, vy, R ωx, R ωy, R ωz, W]. */
  readonly y = new Float64Array(DIM);
  private readonly ye = new Float64Array(DIM);
  private readonly kd = new Float64Array(DIM);
  private readonly atol = new Float64Array(DIM);
  /** Impulse so far, per unit mass. */
  p = -0;
  restitution = false;
  /** The work at which restitution ends. */
  wEnd = -0;
  /** The event tolerance, the speed tolerance, e_e². */
  epsEv = -0;
  atolV = -0;
  ee2 = -0;
  /** The last step proposed away from every slip's zero: where a step restarts after a contact starts to roll. */
  stepFree = 1.5;
  /** Set by enterZero: a slip reached zero (zeroed), and a sliding contact started to roll (stuck). */
  private zeroed = false;
  private stuck = false;
  /** A sliding slip's relaxation rate times its speed (RELAX_MAX): I, C. */
  relaxI = -0;
  relaxC = -0;
  /** Steps in a row rejected by the slaving bound. */
  private slavingRejects = 0;
  /** Set by slavedStart: bit 0 (I), bit 1 (C) for a slaved slip that is zero now. */
  private zeroNow = 0;
  private M = 1.5;
  private R = 1.5;
  V = 1.5;
  outcome: CushionOutcome = 'restitution';
  /** Steps taken (accepted and rejected), and rejected. */
  steps = 0;
  rejected = 0;
  private redecisions = 0;
  /** When set, every accepted step appends samples here. */
  trace: CushionTracePoint[] | null = null;

  /** Integrates one impact with vy > 0 (checked by the caller); the result is left in y and outcome. */
  solve(
    vx: number, vy: number, wx: number, wy: number, wz: number,
    M: number, R: number, h: number, ee: number, muS: number, muW: number, tol: number,
  ): void {
    const model = this.model;
    const s = (h - R) / R;
    const c = Math.sqrt((1 - s) * (1 + s));
    model.setConstants(s, c, muW, muS);
    this.M = M;
    this.R = R;
    const V = Math.sqrt(vx * vx + vy * vy);
    const at = tol * V;
    this.V = V;
    for (let i = 0; i < 5; i++) this.atol[i] = at;
    // The end is where W meets its target: an error dW moves it by dW / (c |vy|).
    this.atol[5] = at * c * vy;
    this.atolV = at;
    this.epsEv = EVENT_FRACTION * at;
    model.epsSlip = HINT_FRACTION * V;
    this.relaxI = 3.5 * muW;
    this.relaxC = 3.5 * muS * (s + c * muW);
    this.p = 0;
    this.restitution = false;
    this.wEnd = 0;
    this.steps = 0;
    this.slavingRejects = 0;
    this.rejected = 0;
    this.redecisions = 0;
    this.outcome = 'restitution';
    this.ee2 = ee * ee;
    const y = this.y;
    y[0] = vx;
    y[1] = vy;
    y[2] = R * wx;
    y[3] = R * wy;
    y[4] = R * wz;
    y[5] = 0;
    this.run(vy);
  }

  /** The integration from y, for an impact that began with vy = vy0. */
  private run(vy0: number): void {
    const { model, rk, y, atol, ee2 } = this;
    const tolV = this.atolV;
    // A slip that is zero at the start (e.g. the table contact of a ball rolling on the cloth).
    const eps0 = ZERO_FRACTION * this.V;
    const zI = this.slipNorm(model.I) <= eps0;
    const zC = this.slipNorm(model.C) <= eps0;
    if ((zI || zC) && this.enterZero(zI, zC)) return this.finishStalled();
    model.derivative(y, rk.k1);
    this.recordTrace(0, 0);
    let step = 0.25 * vy0 / model.c;
    this.stepFree = step;
    this.zeroed = false;
    this.stuck = false;
    let errPrev = FIRST_MEMORY;
    for (;;) {
      if (this.restitution && y[1]! >= -this.epsEv && !(rk.k1[1]! < 0)) {
        // vy is back at zero and the impulse no longer pushes the ball out: the work is at its
        // maximum. (Checked at a step's start too: with friction near 1 the contacts can trade
        // sticking there in steps too short to move.) Unless the rolling conditions, deciding
        // again, push the ball out.
        if (this.redecideAtStall()) continue;
        return this.finishStalled();
      }
      if (++this.steps > MAX_STEPS) {
        throw new Error(`cushionRebound: no end after ${MAX_STEPS} steps (P = ${this.p * this.M} N s, state ${Array.from(y).join(', ')})`);
      }
      // Do not step past the zero of a slaved slip.
      if (model.I.slaved || model.C.slaved) {
        this.zeroNow = 0;
        const d = this.slavedStart(step);
        if (this.zeroNow !== 0) {
          if (this.enterZero((this.zeroNow & 1) !== 0, (this.zeroNow & 2) !== 0)) return this.finishStalled();
          model.derivative(y, rk.k1);
          step = this.afterZero(step, 1);
          continue;
        }
        if (d < step) step = d;
      }
      if (model.I.mode === SLIDE && !model.I.slaved) {
        if (this.pinAlongY()) model.derivative(y, rk.k1);
        // (A slip exactly along ±y with C rolling cannot wobble: its relaxation does not bound the step.)
        const pinned = model.I.slipX(y) === 0 && model.I.rateX(rk.k1) === 0 && model.C.mode === STICK;
        step = this.startOwnDirection(model.I, step, pinned ? 0 : this.relaxI);
      }
      if (model.C.mode === SLIDE && !model.C.slaved) step = this.startOwnDirection(model.C, step, this.relaxC);
      model.I.minDot = Infinity;
      model.C.minDot = Infinity;
      const slavedI = model.I.slaved && model.I.mode === SLIDE;
      const slavedC = model.C.slaved && model.C.mode === SLIDE;
      const uIx = model.I.hintX;
      const uIy = model.I.hintY;
      const uCx = model.C.hintX;
      const uCy = model.C.hintY;
      model.stepping = true;
      rk.step(model, y, step, atol);
      model.stepping = false;
      if (model.I.minDot < -this.epsEv || model.C.minDot < -this.epsEv) {
        // A slip went through zero inside the step: retry up to the interpolated zero.
        this.rejected++;
        let t = 0.5;
        if (model.I.minDot < -this.epsEv) t = Math.min(t, this.crossing(model.I));
        if (model.C.minDot < -this.epsEv) t = Math.min(t, this.crossing(model.C));
        step *= t;
        continue;
      }
      const err = rk.err;
      if (err > 1) {
        this.rejected++;
        step *= Math.max(0.2, 0.9 * invRoot(err));
        continue;
      }
      if (slavedI || slavedC) {
        // What slaving neglects, unseen by the error estimate: the slip lags its slaved direction
        // by about its turn over the step, so the friction is off by about |slip| × turn / (5/2).
        const qe = this.slavingError(slavedI, slavedC, uIx, uIy, uCx, uCy);
        if (qe > tolV) {
          this.rejected++;
          if (++this.slavingRejects >= 3) {
            // The slaved direction jumps however short the step: the slip follows its own.
            this.slavingRejects = 0;
            if (slavedI) this.release(model.I, model.I.slipX(y), model.I.slipY(y), this.slipNorm(model.I));
            if (slavedC) this.release(model.C, model.C.slipX(y), model.C.slipY(y), this.slipNorm(model.C));
            model.derivative(y, rk.k1);
            continue;
          }
          step *= Math.max(0.2, 0.9 * Math.sqrt(tolV / qe));
          continue;
        }
        this.slavingRejects = 0;
      }
      const next = this.accept(step);
      if (next === ENDED) return;
      if (next === AGAIN) continue;
      if (next === LEFT_CONE) {
        // A stuck contact left its cone inside the step: the step ends there.
        const vyBefore = y[1]!;
        rk.denseAll(this.coneExit, y);
        this.p += this.coneExit * step;
        if (this.backAtZero(vyBefore)) return;
        this.leaveStick();
        model.derivative(y, rk.k1);
        continue;
      }
      const rI0 = model.I.mode === SLIDE ? this.slipNorm(model.I) : 0;
      const rC0 = model.C.mode === SLIDE ? this.slipNorm(model.C) : 0;
      const vyStart = y[1]!;
      const dI0 = this.zeroDistanceOf(this.model.I);
      const dC0 = this.zeroDistanceOf(this.model.C);
      y.set(rk.y1);
      rk.swap();
      this.p += step;
      const approach = approachFactor(dI0, this.zeroDistanceOf(this.model.I), dC0, this.zeroDistanceOf(this.model.C));
      if (this.backAtZero(vyStart)) return;
      if (this.settleSlips(rI0, rC0, tolV)) return;
      step = nextStep(step, err, errPrev);
      if (approach === 1 && !this.zeroed && this.slipsClear()) this.stepFree = step;
      step = this.afterZero(step, approach);
      errPrev = errorMemory(err);
    }
  }

  /** Where a stuck contact left its cone in the accepted step (a fraction of it). */
  private coneExit = -0;

  /**
   * The events of an accepted step, located on its continuous extension in order: a stuck
   * contact leaving its cone (LEFT_CONE, at `coneExit`), the end of compression, the work target,
   * vy back at zero. ENDED when the impact ended, AGAIN when y moved to an event and the next step
   * starts there, ACCEPTED when the step is taken whole.
   */
  private accept(step: number): number {
    const { model, rk, y, ee2 } = this;
    let stop = 1;
    let left = false;
    this.dense = false;
    if ((model.I.mode === STICK || model.C.mode === STICK) && model.stickMargin(rk.y1) > 0) {
      this.prepare();
      stop = this.stickRoot(0, 1);
      this.coneExit = stop;
      left = true;
    }
    let vyBack = false;
    let endAt = -1;
    let from = 0;
    const ys = this.ye;
    this.stateAt(stop, ys);
    if (!this.restitution && ys[1]! <= 0) {
      this.prepare();
      from = rk.root(1, 0, 0, stop);
      rk.denseAll(from, this.ye);
      const wc = this.ye[5]!;
      this.wEnd = wc - ee2 * wc;
      this.restitution = true;
      if (this.slipAtZero(this.ye)) {
        // A slip reaches zero together with vy (e.g. head-on with one contact rolling): the step
        // stops here and the rolling conditions decide before restitution starts.
        this.recordTrace(step, from);
        y.set(this.ye);
        this.p += from * step;
        const lim = 10 * this.epsEv;
        if (this.enterZero(model.I.mode === SLIDE && this.slipNorm(model.I) <= lim, model.C.mode === SLIDE && this.slipNorm(model.C) <= lim)) {
          this.finishStalled();
          return ENDED;
        }
        model.derivative(y, rk.k1);
        if (ee2 === 0 || !(rk.k1[1]! < 0)) {
          if (ee2 !== 0) this.finishStalled();
          return ENDED;
        }
        return AGAIN;
      }
      model.derivative(this.ye, this.kd);
      if (ee2 === 0) {
        endAt = from;
      } else if (!(this.kd[1]! < 0)) {
        // The impulse no longer pushes the ball out: restitution can do no work.
        endAt = from;
        this.outcome = 'stalled';
      }
      this.stateAt(stop, ys);
    }
    if (endAt < 0 && this.restitution) {
      if (ys[5]! <= this.wEnd) {
        this.prepare();
        endAt = rk.root(5, this.wEnd, from, stop);
      } else if (ys[1]! >= 0) {
        // vy came back to zero before the work reached its target: it can only fall now.
        // (When compression ended inside this same step the crossing cannot be bracketed: the
        // step's end is used, an approximation only huge friction reaches.)
        this.prepare();
        if (from > 0) endAt = stop;
        else if (y[1]! >= 0) endAt = 0;
        else endAt = this.vyBackRoot(stop);
        this.outcome = 'stalled';
        vyBack = true;
      }
    }
    if (endAt >= 0) {
      this.stateAt(endAt, this.ye);
      this.recordTrace(step, endAt);
      y.set(this.ye);
      this.p += endAt * step;
      if (vyBack && this.redecideAtStall()) {
        this.outcome = 'restitution';
        return AGAIN;
      }
      if (this.outcome === 'stalled') y[1] = 0;
      return ENDED;
    }
    if (this.trace !== null) {
      this.prepare();
      this.recordTrace(step, stop);
    }
    return left ? LEFT_CONE : ACCEPTED;
  }

  /** Whether the continuous extension of the step is ready (prepare). */
  private dense = false;

  private prepare(): void {
    if (!this.dense) this.rk.prepareDense(this.y);
    this.dense = true;
  }

  /** The state at fraction theta of the accepted step into out. */
  private stateAt(theta: number, out: Float64Array): void {
    if (theta < 1) this.rk.denseAll(theta, out);
    else out.set(this.rk.y1);
  }

  /**
   * After an accepted step from vy = vyStart: in restitution, vy risen back to zero (within the
   * event tolerance) ends the impact stalled, unless the rolling conditions, deciding again,
   * push the ball out (redecideAtStall). True when the impact ended.
   */
  private backAtZero(vyStart: number): boolean {
    const vy = this.y[1]!;
    if (!(this.restitution && vy >= -this.epsEv && vy > vyStart)) return false;
    if (this.redecideAtStall()) return false;
    this.finishStalled();
    return true;
  }

  /**
   * After an accepted step (rI0, rC0 the slip speeds at its start): a sliding slip fallen to zero
   * goes through the rolling conditions, and a small one may become slaved. True when both roll.
   */
  private settleSlips(rI0: number, rC0: number, tolV: number): boolean {
    const model = this.model;
    const slideI = model.I.mode === SLIDE;
    const slideC = model.C.mode === SLIDE;
    const rI1 = slideI ? this.slipNorm(model.I) : 0;
    const rC1 = slideC ? this.slipNorm(model.C) : 0;
    const zI = slideI && rI1 <= this.epsEv && (rI1 < rI0 || model.I.minDot < 0);
    const zC = slideC && rC1 <= this.epsEv && (rC1 < rC0 || model.C.minDot < 0);
    if (zI || zC) {
      if (this.enterZero(zI, zC)) {
        this.finishStalled();
        return true;
      }
      model.derivative(this.y, this.rk.k1);
    } else if (this.slaveSmallSlips(tolV)) {
      model.derivative(this.y, this.rk.k1);
    }
    return false;
  }

  /** The result as a plain state (rad/s for the spins; + 0 turns -0 into 0). */
  result(): { vx: number; vy: number; wx: number; wy: number; wz: number } {
    const { y, R } = this;
    return { vx: y[0]! + 0, vy: y[1]! + 0, wx: y[2]! / R + 0, wy: y[3]! / R + 0, wz: y[4]! / R + 0 };
  }

  /**
   * Pinned slips: with C rolling, a cushion slip along ±y stays so; one along it to within
   * PIN_FRACTION whose x part shrinks is put on it (the x part into the offset), or its relaxation
   * would bound every step. True when it was put on ±y (the derivative then changes).
   */
  private pinAlongY(): boolean {
    const m = this.model;
    const ex = m.I.slipX(this.y);
    if (!(m.C.mode === STICK && ex !== 0 && Math.abs(ex) <= PIN_FRACTION * Math.abs(m.I.slipY(this.y)) && ex * m.I.rateX(this.rk.k1) < 0)) return false;
    m.I.offX = m.I.rawX(this.y);
    return true;
  }

  /**
   * A sliding contact that follows its own slip, at a step's start: its starting direction (the
   * hint below epsSlip), and the step limited so that the slip neither passes zero, nor turns,
   * nor relaxes too far in it (limitBySlip).
   */
  private startOwnDirection(ct: Contact, step: number, relax: number): number {
    const ex = ct.slipX(this.y);
    const ey = ct.slipY(this.y);
    const r = Math.sqrt(ex * ex + ey * ey);
    if (!(r > this.model.epsSlip)) {
      ct.refX = ct.hintX;
      ct.refY = ct.hintY;
      return step;
    }
    ct.refX = ex / r;
    ct.refY = ey / r;
    return this.limitBySlip(ex, ey, r, ct.rateX(this.rk.k1), ct.rateY(this.rk.k1), step, relax);
  }

  /** A contact's slip component along its starting direction at y. */
  private along(ct: Contact, y: Float64Array): number {
    return ct.slipX(y) * ct.refX + ct.slipY(y) * ct.refY;
  }

  /**
   * Fraction of the rejected step at which a slip's component along its starting direction
   * crossed zero, interpolated from the step's ends; 0.5 when the end did not cross.
   */
  private crossing(ct: Contact): number {
    const d0 = this.along(ct, this.y);
    const d1 = this.along(ct, this.rk.y1);
    if (!(d0 > 0 && d1 < 0)) return 0.5;
    const t = d0 / (d0 - d1);
    return t < 0.01 ? 0.01 : t > 0.99 ? 0.99 : t;
  }

  /** |slip at the step's end| × the turn of its slaved direction / (5/2), the largest over slaved contacts. */
  private slavingError(slavedI: boolean, slavedC: boolean, uIx: number, uIy: number, uCx: number, uCy: number): number {
    const m = this.model;
    const e = this.e;
    let worst = 0;
    for (let i = 0; i < 2; i++) {
      const ct = i === 0 ? m.I : m.C;
      if (!(i === 0 ? slavedI : slavedC) || !ct.slaved) continue;
      this.slipOf(ct, this.rk.y1, e);
      const dx = ct.hintX - (i === 0 ? uIx : uCx);
      const dy = ct.hintY - (i === 0 ? uIy : uCy);
      const err = Math.sqrt((e.x * e.x + e.y * e.y) * (dx * dx + dy * dy)) / 2.5;
      if (err > worst) worst = err;
    }
    return worst;
  }

  /**
   * The impulse over which a held slip's neglected rate could act: V, or in restitution the
   * impulse the work still needs at the current vy, if longer.
   */
  private holdSpan(): number {
    const vy = this.y[1]!;
    if (this.restitution && vy < 0) {
      const left = (this.y[5]! - this.wEnd) / (this.model.c * -vy);
      if (left > this.V) return left;
    }
    return this.V;
  }

  /** |rate| of a contact's slip from a derivative k. */
  private rateSpeed(ct: Contact, k: Float64Array): number {
    const rx = ct.rateX(k);
    const ry = ct.rateY(k);
    return Math.sqrt(rx * rx + ry * ry);
  }

  /** A slaved contact with slip (ex, ey), |slip| = r, follows its own direction again. */
  private release(ct: Contact, ex: number, ey: number, r: number): void {
    ct.slave(false, false, ct.hintX, ct.hintY);
    if (!(r > this.model.epsSlip)) return;
    ct.refX = ex / r;
    ct.refY = ey / r;
  }

  private readonly e = { x: -0, y: -0 };

  /** A contact's effective slip at y into out. */
  private slipOf(ct: Contact, y: Float64Array, out: { x: number; y: number }): void {
    out.x = ct.slipX(y);
    out.y = ct.slipY(y);
  }

  /**
   * At a step's start, for each slaved contact: re-solve its direction, release it if it grew
   * past QS_EXIT, hold it if its rates vanished, and return the step after which its slip would
   * reach zero (or grow past QS_GROW × V); marks zeroNow for one that is zero now.
   */
  private slavedStart(step: number): number {
    const m = this.model;
    const y = this.y;
    const e = this.e;
    let d = Infinity;
    for (const ct of m.contacts) {
      if (!ct.slaved || ct.mode !== SLIDE) continue;
      this.slipOf(ct, y, e);
      const r = Math.sqrt(e.x * e.x + e.y * e.y);
      if (ct.held) {
        // A held slip stays held while its rates stay negligible (with a margin of ten).
        if (this.rateSpeed(ct, this.rk.k1) * this.holdSpan() > 10 * this.epsEv) this.release(ct, e.x, e.y, r);
        continue;
      }
      if (r > m.epsSlip && r <= QS_HOLD_RHO * this.V && this.rateSpeed(ct, this.rk.k1) * this.holdSpan() <= this.epsEv) {
        ct.slave(true, true, e.x / r, e.y / r);
        continue;
      }
      const lam = ct === m.I ? m.slavedI(y) : m.slavedC(y);
      if (!(lam === lam) || (lam > 0 && r > QS_EXIT * this.V)) {
        // No slaved direction (C with I rolling, off the y axis) or grown: it follows its own.
        this.release(ct, e.x, e.y, r);
        continue;
      }
      ct.slave(true, false, m.ux, m.uy);
      const along = e.x * m.ux + e.y * m.uy;
      if (lam < 0 && r > m.epsSlip) {
        // A shrinking slaved slip only loses its part along u: once what is across u is as
        // large, it is at its closest to zero: zero within the event band, else released.
        const px = e.x - along * m.ux;
        const py = e.y - along * m.uy;
        if (!(along > Math.sqrt(px * px + py * py))) {
          if (r <= 10 * this.epsEv) this.zeroNow |= ct === m.I ? 1 : 2;
          else this.release(ct, e.x, e.y, r);
          continue;
        }
      }
      if (lam < 0 && along > 0) {
        if (along / -lam < d) d = along / -lam;
      } else if (lam > 0) {
        const t = (QS_GROW * this.V - r) / lam;
        if (t > 0 && t < d) d = t;
      }
    }
    return d < step ? d : step;
  }

  /**
   * After an accepted step: a sliding slip below QS_RHO × V whose direction already follows the
   * slaved one (δ × slip <= QS_FRACTION × tolerance) becomes slaved, its offset absorbing the
   * difference; one whose rates vanish is held. True when a contact changed.
   */
  private slaveSmallSlips(tolV: number): boolean {
    const m = this.model;
    const y = this.y;
    const e = this.e;
    let changed = false;
    for (const ct of m.contacts) {
      if (ct.mode !== SLIDE || ct.slaved) continue;
      this.slipOf(ct, y, e);
      const ex = e.x;
      const ey = e.y;
      const r = Math.sqrt(ex * ex + ey * ey);
      if (r > m.epsSlip && r <= QS_HOLD_RHO * this.V && this.rateSpeed(ct, this.rk.k1) * this.holdSpan() <= this.epsEv) {
        // Its rates vanish along its own direction (friction at the both-rolling threshold).
        ct.slave(true, true, ex / r, ey / r);
        changed = true;
        continue;
      }
      if (!(r <= QS_RHO * this.V) || !(r > 0)) continue;
      const lam = ct === m.I ? m.slavedI(y) : m.slavedC(y);
      if (!(lam === lam)) continue;
      // Never slaved to a direction in which it would grow while it shrinks (or the reverse).
      const k1 = this.rk.k1;
      const rate = ex * ct.rateX(k1) + ey * ct.rateY(k1);
      if ((lam > 0) !== (rate > 0)) continue;
      const dx = ex / r - m.ux;
      const dy = ey / r - m.uy;
      if (!(Math.sqrt(dx * dx + dy * dy) * r <= QS_FRACTION * tolV)) continue;
      ct.offX += ex - r * m.ux;
      ct.offY += ey - r * m.uy;
      ct.slave(true, ct.held, m.ux, m.uy);
      changed = true;
    }
    return changed;
  }

  /** Whether a sliding contact's slip is within 10 event tolerances of zero at ys. */
  private slipAtZero(ys: Float64Array): boolean {
    const m = this.model;
    const lim = 10 * this.epsEv;
    const e = this.e;
    for (const ct of m.contacts) {
      if (ct.mode !== SLIDE) continue;
      this.slipOf(ct, ys, e);
      if (e.x * e.x + e.y * e.y <= lim * lim) return true;
    }
    return false;
  }

  /**
   * The step shortened so that a sliding slip (ex, ey), |slip| = r, changing at (rx, ry) neither
   * passes zero (the step is then aimed at it) nor turns more than TURN_MAX, nor exceeds
   * RELAX_MAX over its relaxation rate (relax / r).
   */
  private limitBySlip(ex: number, ey: number, r: number, rx: number, ry: number, step: number, relax: number): number {
    const rate = (ex * rx + ey * ry) / r;
    if (rate < 0 && r <= -rate * step) step = -r / rate;
    const turn = Math.abs(rx * ey - ry * ex) / r;
    if (turn * step > TURN_MAX * r) step = TURN_MAX * r / turn;
    if (relax * step > RELAX_MAX * r) step = RELAX_MAX * r / relax;
    return step;
  }

  /** Impulse to the zero of contact 0's (I) or 1's (C) slip, sliding on its own direction with friction; else Infinity. */
  private zeroDistanceOf(ct: Contact): number {
    const m = this.model;
    if (ct.mode !== SLIDE || ct.slaved) return Infinity;
    if (!(ct.mu > 0)) return Infinity;
    const k = this.rk.k1;
    const e = this.e;
    this.slipOf(ct, this.y, e);
    const r = Math.sqrt(e.x * e.x + e.y * e.y);
    if (!(r > m.epsSlip)) return Infinity;
    const rx = ct.rateX(k);
    const ry = ct.rateY(k);
    return zeroDistance(r, (e.x * rx + e.y * ry) / r);
  }

  /** |effective slip| of contact 0 (I) or 1 (C) now. */
  private slipNorm(ct: Contact): number {
    const e = this.e;
    this.slipOf(ct, this.y, e);
    return Math.sqrt(e.x * e.x + e.y * e.y);
  }

  /**
   * Slips of I (zI) and/or C (zC) are zero now: their residuals become offsets and the rolling
   * conditions decide each contact's mode. True when both roll (the impact cannot progress).
   */
  private enterZero(zI: boolean, zC: boolean): boolean {
    const m = this.model;
    const y = this.y;
    const slideI = m.I.mode === SLIDE;
    const slideC = m.C.mode === SLIDE;
    if (zI) m.I.zeroAt(y);
    if (zC) m.C.zeroAt(y);
    let both = false;
    if ((zI || m.I.mode === STICK) && (zC || m.C.mode === STICK)) both = m.onsetBoth(y);
    else if (zC) m.onsetC(y);
    else m.onsetI(y);
    this.zeroed = true;
    if ((slideI && m.I.mode === STICK) || (slideC && m.C.mode === STICK)) this.stuck = true;
    return both;
  }

  /**
   * The next step from the control's proposal and the approach factor of the step just taken;
   * after a slip reached zero and its contact started to roll, at least RESTART_FRACTION of
   * stepFree (the rolling branch is smooth; growing back from the approach's tiny steps is slow).
   */
  private afterZero(proposal: number, approach: number): number {
    if (!this.zeroed) return proposal * approach;
    this.zeroed = false;
    if (!this.stuck) return proposal;
    this.stuck = false;
    const restart = RESTART_FRACTION * this.stepFree;
    return proposal < restart ? restart : proposal;
  }

  /** Whether every sliding contact follows its own direction with a slip above QS_RHO × V. */
  private slipsClear(): boolean {
    const m = this.model;
    const lim = QS_RHO * this.V;
    if (m.I.mode === SLIDE && (m.I.slaved || !(this.slipNorm(m.I) > lim))) return false;
    if (m.C.mode === SLIDE && (m.C.slaved || !(this.slipNorm(m.C) > lim))) return false;
    return true;
  }

  /** The stuck contact needs more than its friction cone: it starts to slip, slaved, opposite to that friction. */
  private leaveStick(): void {
    const m = this.model;
    const y = this.y;
    m.stickMargin(y); // (fills the rolling frictions at y)
    if (m.I.mode === STICK) {
      const n = Math.sqrt(m.gx * m.gx + m.gy * m.gy);
      m.I.mode = SLIDE;
      m.I.zeroAt(y);
      m.I.slave(true, false, n > 0 ? -m.gx / n : m.I.hintX, n > 0 ? -m.gy / n : m.I.hintY);
    } else {
      const n = Math.sqrt(m.hx * m.hx + m.hy * m.hy);
      m.C.mode = SLIDE;
      m.C.zeroAt(y);
      m.C.slave(true, false, n > 0 ? -m.hx / n : m.C.hintX, n > 0 ? -m.hy / n : m.C.hintY);
    }
  }

  /**
   * vy came back to zero in restitution with a sliding slip within STALL_ZERO event tolerances
   * of zero: that slip is taken as zero and the rolling conditions decide again; true (the
   * impact goes on) when the impulse then pushes the ball out, at most REDECISIONS times.
   */
  private redecideAtStall(): boolean {
    if (this.redecisions >= REDECISIONS) return false;
    this.redecisions++;
    const m = this.model;
    const zI = m.I.mode === SLIDE && this.slipNorm(m.I) <= STALL_ZERO * this.epsEv;
    const zC = m.C.mode === SLIDE && this.slipNorm(m.C) <= STALL_ZERO * this.epsEv;
    if (!zI && !zC) return false;
    if (this.enterZero(zI, zC)) return false;
    m.derivative(this.y, this.rk.k1);
    return this.rk.k1[1]! < 0;
  }

  /** Both contacts roll, or the ball recedes no more: the impact ends with vy = 0. */
  private finishStalled(): void {
    this.outcome = 'stalled';
    this.y[1] = 0;
  }

  /** Where an event g(θ) (> 0 before it) happens in [lo, hi]: the event side of the bracket. */
  private falsi(g: (theta: number) => number, lo: number, hi: number): number {
    const flo = g(lo);
    if (!(flo > 0)) return lo;
    const fhi = g(hi);
    return fhi > 0 ? hi : illinois(g, lo, hi, flo, fhi, 0, 1e-15);
  }

  /** Where a stuck contact leaves its cone in the step. */
  private stickRoot(lo: number, hi: number): number {
    return this.falsi((theta) => {
      this.rk.denseAll(theta, this.kd);
      return -this.model.stickMargin(this.kd);
    }, lo, hi);
  }

  /** Where vy comes back to zero in the step. */
  private vyBackRoot(hi: number): number {
    return this.falsi((theta) => -this.rk.denseAt(theta, 1), 0, hi);
  }

  /** Appends samples of the last step (fractions up to `upTo`) when tracing. */
  private recordTrace(step: number, upTo: number): void {
    const trace = this.trace;
    if (trace === null) return;
    const n = step === 0 ? 1 : 8;
    for (let j = step === 0 ? 0 : 1; j <= n; j++) {
      const theta = step === 0 ? 0 : (upTo * j) / n;
      if (step === 0) this.ye.set(this.y);
      else this.rk.denseAll(theta, this.ye);
      const m = this.model;
      const { R, M, ye: y } = this;
      trace.push({
        P: (this.p + theta * step) * M,
        vx: y[0]!,
        vy: y[1]!,
        wx: y[2]! / R,
        wy: y[3]! / R,
        wz: y[4]! / R,
        xI: y[0]! + m.s * y[3]! - m.c * y[4]!,
        yI: -m.s * y[1]! + y[2]!,
        xC: y[0]! - y[3]!,
        yC: y[1]! + y[2]!,
        W: y[5]! * M,
        stickI: m.I.mode === STICK,
        stickC: m.C.mode === STICK,
      });
    }
  }
}
