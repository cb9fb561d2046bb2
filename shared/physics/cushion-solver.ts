// The event-driven integration of one cushion impact in the impulse (Mathavan et al. 2010):
// compression until vy = 0 (work W_c), restitution until the work done since then reaches
// e_e² W_c. Between events an adaptive Dormand-Prince 5(4) step (cushion-dopri.ts); the events:
//  - a slipping contact's slip reaches zero: predicted from its rate and stepped onto
//    (a Newton iteration on the slip speed), then the rolling conditions (eqs. 15a/15b) decide
//    whether the contact rolls (sticks) or keeps slipping in a new direction;
//  - a rolling contact needs more friction than μ × its normal: located on the continuous
//    extension (the rolling branch is smooth through that point), the contact starts to slip;
//  - vy = 0 (end of compression, W_c recorded) and the work target (end), located on the
//    continuous extension;
//  - the ball can recede no more although the target is not reached ('stalled', see
//    cushion-types.ts): ends there with vy = 0.
// Only + - * / and Math.sqrt. A step count cap throws: it never returns a wrong answer.
import { denseRoot } from './cushion-dense.ts';
import { Dopri5, DIM } from './cushion-dopri.ts';
import { FAST_END, FAST_SETTLE, runFast } from './cushion-fast.ts';
import type { FastHost } from './cushion-fast.ts';
import { CushionModel, SLIDE, STICK } from './cushion-model.ts';
import type { CushionOutcome } from './cushion-types.ts';
import {
  approachFactor, errorMemory, EVENT_FRACTION, FIRST_MEMORY, HINT_FRACTION, invRoot, MAX_STEPS, nextStep,
  PIN_FRACTION, QS_EXIT, QS_FRACTION, QS_GROW, QS_HOLD_RHO, QS_RHO, RELAX_MAX, RESTART_FRACTION, TURN_MAX,
  ZERO_FRACTION,
  zeroDistance,
} from './cushion-control.ts';

export { MAX_STEPS } from './cushion-control.ts';

/** How many stalls an impact may re-decide (redecideAtStall): a guard against trading modes. */
const REDECISIONS = 4;
/**
 * A sliding slip within this many event tolerances of zero (10 times the solver's tolerance of
 * the speed) is taken as zero at a stall (redecideAtStall). At 10, 6 of 6,000 draws near the
 * both-rolling threshold and an 85.57° impact still stalled 2e-3 to 5.7e-2 V0 from the
 * reference, their slips 2e-6 to 1e-5 of the speed when vy came back; at 30 and at 100 all
 * seven end as the reference does, within 1.7e-6 V0 of it (docs/cushion.md, Limits).
 */
const STALL_ZERO = 100;

// Event functions on the continuous extension, signed so that > 0 is before the event.
const EV_VY = 0;
const EV_VY_BACK = 1;
const EV_WORK = 2;
const EV_STICK = 3;

/** One sample of the impact's history (for figures and checks). */
export interface CushionTracePoint {
  /** Impulse at the cushion so far (N s). */
  readonly P: number;
  readonly vx: number;
  readonly vy: number;
  readonly wx: number;
  readonly wy: number;
  readonly wz: number;
  /** Slip velocity components at I (cushion) and C (table), m/s. */
  readonly xI: number;
  readonly yI: number;
  readonly xC: number;
  readonly yC: number;
  /** Work of the normal force at I so far (J); falls during restitution. */
  readonly W: number;
  readonly stickI: boolean;
  readonly stickC: boolean;
}

export class CushionSolver implements FastHost {
  readonly model = new CushionModel();
  private readonly rk = new Dopri5();
  /** Current state (then the result) in internal variables [vx, vy, R wx, R wy, R wz, W]. */
  readonly y = new Float64Array(DIM);
  private readonly ye = new Float64Array(DIM);
  private readonly kd = new Float64Array(DIM);
  private readonly atol = new Float64Array(DIM);
  p = -0;
  /** False during compression, true during restitution. */
  restitution = false;
  wEnd = -0;
  epsEv = -0;
  atolV = -0;
  atolW = -0;
  ee2 = -0;
  /** Step control, shared with the inner loop (cushion-fast.ts): see FastHost. */
  step = -0;
  errPrev = -0;
  lastErr = -0;
  lastApproach = 1;
  /**
   * The last step proposed away from every slip's zero (approachFactor 1, every sliding slip above
   * QS_RHO of the speed): where a step restarts after a contact starts to roll (afterZero).
   */
  stepFree = 1.5;
  /** Set by enterZero: a slip reached zero (zeroed), and a sliding contact started to roll (stuck). */
  private zeroed = false;
  private stuck = false;
  rI0 = -0;
  rC0 = -0;
  vy0 = -0;
  /** How fast a sliding slip's direction relaxes, times its speed (see RELAX_MAX): I, C. */
  relaxI = -0;
  relaxC = -0;
  /** Steps in a row rejected by the slaving bound (see solve). */
  private slavingRejects = 0;
  /** Whether the inner loop for two slipping contacts is used (off only to test it). */
  fastLoop = true;
  innerSteps = 0;
  /** Set by slavedStart: bit 0 (I) and bit 1 (C) for a slaved slip that is zero now. */
  private zeroNow = 0;
  private M = 1.5;
  private R = 1.5;
  V = 1.5;
  /** How the last impact ended. */
  outcome: CushionOutcome = 'restitution';
  /** Steps taken (accepted and rejected) by the last impact. */
  steps = 0;
  rejected = 0;
  /** Stalls re-decided this impact (redecideAtStall; at most REDECISIONS). */
  private redecisions = 0;
  /** When set, every accepted step appends samples here. */
  trace: CushionTracePoint[] | null = null;

  /**
   * Integrates one impact with vy > 0 (checked by the caller). The result is left in y
   * (internal variables) and outcome.
   */
  solve(
    vx: number, vy: number, wx: number, wy: number, wz: number,
    M: number, R: number, h: number, ee: number, muS: number, muW: number,
    tol: number,
  ): void {
    this.begin(vx, vy, M, R, h, ee, muS, muW, tol);
    const y = this.y;
    y[0] = vx;
    y[1] = vy;
    y[2] = R * wx;
    y[3] = R * wy;
    y[4] = R * wz;
    y[5] = 0;
    this.run(vy);
  }

  /**
   * Continues an impact that began with velocity (vx0, vy0) (its tolerances are that impact's)
   * from the internal state `from` = [vx, vy, R ωx, R ωy, R ωz, W] at impulse p (per unit mass),
   * in compression or restitution (with the work's target wEnd): the express path hands over
   * here when it leaves its branch (cushion-express.ts).
   */
  resume(
    vx0: number, vy0: number, M: number, R: number, h: number, ee: number, muS: number, muW: number,
    tol: number, from: Float64Array, restitution: boolean, wEnd: number, p: number,
  ): void {
    this.begin(vx0, vy0, M, R, h, ee, muS, muW, tol);
    copy6(from, this.y);
    this.restitution = restitution;
    this.wEnd = wEnd;
    this.p = p;
    this.run(vy0);
  }

  /** The constants and tolerances of an impact that begins with velocity (vx, vy). */
  private begin(
    vx: number, vy: number, M: number, R: number, h: number, ee: number, muS: number, muW: number, tol: number,
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
    const atol = this.atol;
    for (let i = 0; i < 5; i++) atol[i] = at;
    // The end is where W meets its target: an error dW moves it by dW / (c |vy|).
    atol[5] = at * c * vy;
    this.atolV = at;
    this.atolW = atol[5]!;
    this.epsEv = EVENT_FRACTION * at;
    model.epsSlip = HINT_FRACTION * V;
    this.relaxI = 3.5 * muW;
    this.relaxC = 3.5 * muS * (s + c * muW);
    this.p = 0;
    this.restitution = false;
    this.wEnd = 0;
    this.steps = 0;
    this.slavingRejects = 0;
    this.innerSteps = 0;
    this.rejected = 0;
    this.redecisions = 0;
    this.outcome = 'restitution';
    this.ee2 = ee * ee;
  }

  /** The integration from y, for an impact that began with vy = vy0. */
  private run(vy0: number): void {
    const model = this.model;
    const rk = this.rk;
    const y = this.y;
    const c = model.c;
    const M = this.M;
    const V = this.V;
    const tolV = this.atolV;
    const ee2 = this.ee2;
    const atol = this.atol;

    // A slip that is zero at the start (e.g. a ball rolling on the cloth).
    const eps0 = ZERO_FRACTION * V;
    const zI = this.slipNorm(0) <= eps0;
    const zC = this.slipNorm(1) <= eps0;
    if ((zI || zC) && this.enterZero(zI, zC)) {
      this.finishStalled();
      return;
    }
    model.derivative(y, rk.k1);
    this.recordTrace(0, 0);

    let step = 0.25 * vy0 / c;
    this.stepFree = step;
    this.zeroed = false;
    this.stuck = false;
    let errPrev = FIRST_MEMORY;
    for (;;) {
      if (this.fastLoop && this.trace === null && (model.qsI || model.qsC) && model.modeI === SLIDE &&
        model.modeC === SLIDE) {
        this.releaseGrown();
      }
      if (this.fastLoop && this.trace === null && model.modeI === SLIDE && model.modeC === SLIDE &&
        !model.qsI && !model.frozenC && (!model.qsC || this.slipNorm(1) <= model.epsSlip)) {
        // Both contacts slip (the table contact perhaps slaved, growing from zero): the inner
        // loop takes these steps faster (cushion-fast.ts).
        this.step = step;
        this.errPrev = errPrev;
        const code = runFast(this, y, rk.k1);
        step = this.step;
        errPrev = this.errPrev;
        if (code === FAST_END) return;
        if (code === FAST_SETTLE) {
          if (this.backAtZero(this.vy0)) return;
          if (this.settleSlips(this.rI0, this.rC0, tolV)) return;
          step = this.afterZero(nextStep(step, this.lastErr, errPrev), this.lastApproach);
          errPrev = errorMemory(this.lastErr);
          continue;
        }
      }
      if (this.restitution && y[1]! >= -this.epsEv && !(rk.k1[1]! < 0)) {
        // vy is back at zero (within the event tolerance) and the impulse no longer pushes the
        // ball out: the work has reached its maximum (outcome 'stalled', as when vy crosses 0
        // inside a step). Checked at a step's start too: with friction near 1 the contacts can
        // trade sticking there in steps too short to move. Unless a sliding slip is near zero
        // and the rolling conditions, deciding again, push the ball out (redecideAtStall).
        if (this.redecideAtStall()) continue;
        this.finishStalled();
        return;
      }
      if (++this.steps > MAX_STEPS) {
        throw new Error(
          `cushionRebound: no end after ${MAX_STEPS} steps (P = ${this.p * M} N s, state ${Array.from(y).join(', ')})`,
        );
      }
      // Slip-zero prediction: do not step past the point where a slip speed reaches zero.
      if (model.qsI || model.qsC) {
        this.zeroNow = 0;
        const d = this.slavedStart(step);
        if (this.zeroNow !== 0) {
          if (this.enterZero((this.zeroNow & 1) !== 0, (this.zeroNow & 2) !== 0)) {
            this.finishStalled();
            return;
          }
          model.derivative(y, rk.k1);
          step = this.afterZero(step, 1);
          continue;
        }
        if (d < step) step = d;
      }
      if (model.modeI === SLIDE && !model.qsI) {
        let ex = model.slipIx(y);
        const ey = model.slipIy(y);
        if (model.modeC === STICK && ex !== 0 && Math.abs(ex) <= PIN_FRACTION * Math.abs(ey) && ex * model.rateIx(rk.k1) < 0) {
          // With the table contact rolling, a cushion slip along ±y stays so (below). One that is
          // along it to within PIN_FRACTION, its x part shrinking (the line attracts it: its
          // direction relaxes to it at a rate ~ 1/slip), is put on it, the x part taken into the
          // offset: an error of at most PIN_FRACTION of the slip, where following the x part's
          // relaxation would bound every step by it (seen at 5e-8 of the slip on high-friction
          // impacts that then crept to the step cap).
          model.offIx = y[0]! + model.s * y[3]! - model.c * y[4]!;
          ex = model.slipIx(y);
          model.derivative(y, rk.k1);
        }
        const r = Math.sqrt(ex * ex + ey * ey);
        if (r > model.epsSlip) {
          model.refIx = ex / r;
          model.refIy = ey / r;
          const rx = model.rateIx(rk.k1);
          // A cushion slip exactly along ±y while the table contact rolls stays so (its x rate is
          // exactly zero: no friction acts along x at either contact): its direction cannot
          // wobble, so its relaxation does not bound the step (RELAX_MAX).
          const pinned = ex === 0 && rx === 0 && model.modeC === STICK;
          step = this.limitBySlip(ex, ey, r, rx, model.rateIy(rk.k1), step, pinned ? 0 : this.relaxI);
        } else {
          model.refIx = model.hintIx;
          model.refIy = model.hintIy;
        }
      }
      if (model.modeC === SLIDE && !model.qsC) {
        const ex = model.slipCx(y);
        const ey = model.slipCy(y);
        const r = Math.sqrt(ex * ex + ey * ey);
        if (r > model.epsSlip) {
          model.refCx = ex / r;
          model.refCy = ey / r;
          step = this.limitBySlip(ex, ey, r, model.rateCx(rk.k1), model.rateCy(rk.k1), step, this.relaxC);
        } else {
          model.refCx = model.hintCx;
          model.refCy = model.hintCy;
        }
      }
      model.minDotI = Infinity;
      model.minDotC = Infinity;
      const slavedI = model.qsI && model.modeI === SLIDE;
      const slavedC = model.qsC && model.modeC === SLIDE;
      const uIx = model.hintIx;
      const uIy = model.hintIy;
      const uCx = model.hintCx;
      const uCy = model.hintCy;
      model.stepping = true;
      const fm = model.fastMode();
      if (fm >= 0) rk.stepFast(model, fm, y, step, atol);
      else rk.step(model, y, step, atol);
      model.stepping = false;
      const tol0 = -this.epsEv;
      if (model.minDotI < tol0 || model.minDotC < tol0) {
        // A slip went through zero inside the step (deeper than the event tolerance): the
        // sliding equations do not hold past it. Retry up to the interpolated zero.
        this.rejected++;
        let t = 0.5;
        if (model.minDotI < tol0) t = Math.min(t, this.crossing(0));
        if (model.minDotC < tol0) t = Math.min(t, this.crossing(1));
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
        // What slaving neglects, which the error estimate cannot see: the slip lags its slaved
        // direction by about (its turn) × (the slip's relaxation time), so the friction's
        // direction is off by that much, about |slip| × turn / (5/2) over the step (5/2 the
        // smallest weight of the friction in the slip's own rates). Bounded like a step error.
        const qe = this.slavingError(slavedI, slavedC, uIx, uIy, uCx, uCy);
        if (qe > tolV) {
          this.rejected++;
          if (++this.slavingRejects >= 3) {
            // The slaved direction jumps however short the step (two roots of its equation
            // trade places): slaving does not describe this slip; it follows its own direction.
            this.slavingRejects = 0;
            if (slavedI) this.release(0, model.slipIx(y), model.slipIy(y), this.slipNorm(0));
            if (slavedC) this.release(1, model.slipCx(y), model.slipCy(y), this.slipNorm(1));
            model.derivative(y, rk.k1);
            continue;
          }
          step *= Math.max(0.2, 0.9 * Math.sqrt(tolV / qe));
          continue;
        }
        this.slavingRejects = 0;
      }

      // Accepted. Events located on the continuous extension, in order.
      let stop = 1;
      let leave = false;
      let dense = false;
      if ((model.modeI === STICK || model.modeC === STICK) && model.stickMargin(rk.y1) > 0) {
        rk.prepareDense(y);
        dense = true;
        stop = this.root(EV_STICK, 0, 0, 1);
        leave = true;
      }
      let vyBack = false;
      let endAt = -1;
      let from = 0;
      const ys = this.ye;
      if (stop < 1) rk.denseAll(stop, ys);
      else copy6(rk.y1, ys);
      if (!this.restitution && ys[1]! <= 0) {
        if (!dense) {
          rk.prepareDense(y);
          dense = true;
        }
        from = this.root(EV_VY, 0, 0, stop);
        rk.denseAll(from, this.ye);
        const wc = this.ye[5]!;
        this.wEnd = wc - ee2 * wc;
        this.restitution = true;
        if (this.slipAtZero(this.ye)) {
          // A slip reaches zero together with vy (e.g. head-on with one contact rolling): stop
          // the step here and let the rolling conditions decide before restitution starts.
          this.recordTrace(step, from);
          copy6(this.ye, y);
          this.p += from * step;
          if (this.enterZero(model.modeI === SLIDE && this.slipNorm(0) <= 10 * this.epsEv,
            model.modeC === SLIDE && this.slipNorm(1) <= 10 * this.epsEv)) {
            this.finishStalled();
            return;
          }
          model.derivative(y, rk.k1);
          if (ee2 === 0 || !(rk.k1[1]! < 0)) {
            if (ee2 !== 0) this.finishStalled();
            return;
          }
          continue;
        }
        model.derivative(this.ye, this.kd);
        if (ee2 === 0) {
          endAt = from;
        } else if (!(this.kd[1]! < 0)) {
          // The impulse no longer pushes the ball out: restitution can do no work.
          endAt = from;
          this.outcome = 'stalled';
        }
        if (stop < 1) rk.denseAll(stop, ys);
        else copy6(rk.y1, ys);
      }
      if (endAt < 0 && this.restitution) {
        if (ys[5]! <= this.wEnd) {
          if (!dense) {
            rk.prepareDense(y);
            dense = true;
          }
          endAt = this.root(EV_WORK, this.wEnd, from, stop);
        } else if (ys[1]! >= 0) {
          // vy came back to zero before the work reached its target: it can only fall now.
          if (!dense) {
            rk.prepareDense(y);
            dense = true;
          }
          // (When compression ended inside this same step the crossing cannot be bracketed;
          // the step's end is used, an approximation for a case only huge friction reaches.)
          if (from > 0) endAt = stop;
          else if (y[1]! >= 0) endAt = 0;
          else endAt = this.root(EV_VY_BACK, 0, 0, stop);
          this.outcome = 'stalled';
          vyBack = true;
        }
      }
      if (endAt >= 0) {
        if (endAt < 1) rk.denseAll(endAt, this.ye);
        else copy6(rk.y1, this.ye);
        this.recordTrace(step, endAt);
        copy6(this.ye, y);
        this.p += endAt * step;
        if (vyBack && this.redecideAtStall()) {
          this.outcome = 'restitution';
          continue;
        }
        if (this.outcome === 'stalled') y[1] = 0;
        return;
      }
      if (leave) {
        this.recordTrace(step, stop);
        const vyStart = y[1]!;
        rk.denseAll(stop, y);
        this.p += stop * step;
        if (this.backAtZero(vyStart)) return;
        this.leaveStick();
        model.derivative(y, rk.k1);
        continue;
      }
      if (this.trace !== null) {
        if (!dense) rk.prepareDense(y);
        this.recordTrace(step, 1);
      }
      const rI0 = model.modeI === SLIDE ? this.slipNorm(0) : 0;
      const vyStart = y[1]!;
      const rC0 = model.modeC === SLIDE ? this.slipNorm(1) : 0;
      const dI0 = this.zeroDistanceOf(0);
      const dC0 = this.zeroDistanceOf(1);
      copy6(rk.y1, y);
      rk.swap();
      this.p += step;
      const approach = approachFactor(dI0, this.zeroDistanceOf(0), dC0, this.zeroDistanceOf(1));
      if (this.backAtZero(vyStart)) return;
      if (this.settleSlips(rI0, rC0, tolV)) return;
      step = nextStep(step, err, errPrev);
      if (approach === 1 && !this.zeroed && this.slipsClear()) this.stepFree = step;
      step = this.afterZero(step, approach);
      errPrev = errorMemory(err);
    }
  }

  /**
   * After an accepted step from vy = vyStart, before the slips are settled: in restitution, vy
   * that rose back to zero (within the event tolerance) ends the impact stalled, as when vy
   * crosses 0 inside a step. Checked before the rolling conditions decide at a slip zero met at
   * the same instant (with the table contact rolling, the cushion slip along y is
   * -(1 + sinθ) vy, so it reaches zero exactly with vy). Unless a sliding slip is within the
   * event band of zero there and the rolling conditions, deciding again, choose a branch that
   * pushes the ball out (redecideAtStall): then the impact goes on, as in the reference. True
   * when the impact ended.
   */
  private backAtZero(vyStart: number): boolean {
    const vy = this.y[1]!;
    if (!(this.restitution && vy >= -this.epsEv && vy > vyStart)) return false;
    if (this.redecideAtStall()) return false;
    this.finishStalled();
    return true;
  }

  /**
   * After an accepted step (y and rk.k1 at its end; rI0, rC0 the slip speeds at its start):
   * a slipping contact whose slip fell (nearly) to zero goes through the rolling conditions,
   * and a small slip may become slaved. True when the impact ended (both contacts roll).
   */
  private settleSlips(rI0: number, rC0: number, tolV: number): boolean {
    const model = this.model;
    const slideI = model.modeI === SLIDE;
    const slideC = model.modeC === SLIDE;
    const rI1 = slideI ? this.slipNorm(0) : 0;
    const rC1 = slideC ? this.slipNorm(1) : 0;
    const zI = slideI && rI1 <= this.epsEv && (rI1 < rI0 || model.minDotI < 0);
    const zC = slideC && rC1 <= this.epsEv && (rC1 < rC0 || model.minDotC < 0);
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

  /** The result as a plain state (rad/s for the spins). */
  result(): { vx: number; vy: number; wx: number; wy: number; wz: number } {
    const y = this.y;
    const R = this.R;
    // + 0 turns -0 into 0.
    return { vx: y[0]! + 0, vy: y[1]! + 0, wx: y[2]! / R + 0, wy: y[3]! / R + 0, wz: y[4]! / R + 0 };
  }

  /**
   * Fraction of the rejected step at which contact 0 (I) or 1 (C)'s slip component along its
   * starting direction crossed zero, interpolated linearly from the step's two ends; 0.5 when
   * the end did not cross (a crossing and return inside the step).
   */
  private crossing(contact: number): number {
    const m = this.model;
    const y = this.y;
    const y1 = this.rk.y1;
    const d0 = contact === 0
      ? m.slipIx(y) * m.refIx + m.slipIy(y) * m.refIy
      : m.slipCx(y) * m.refCx + m.slipCy(y) * m.refCy;
    const d1 = contact === 0
      ? m.slipIx(y1) * m.refIx + m.slipIy(y1) * m.refIy
      : m.slipCx(y1) * m.refCx + m.slipCy(y1) * m.refCy;
    if (!(d0 > 0 && d1 < 0)) return 0.5;
    const t = d0 / (d0 - d1);
    return t < 0.01 ? 0.01 : t > 0.99 ? 0.99 : t;
  }

  /**
   * For the slaved contacts of the step just taken (their slaved directions at its start given):
   * the largest |slip at the end| × turn of the slaved direction / (5/2), the part of the motion
   * slaving neglects over the step.
   */
  private slavingError(
    slavedI: boolean, slavedC: boolean, uIx: number, uIy: number, uCx: number, uCy: number,
  ): number {
    const m = this.model;
    const y1 = this.rk.y1;
    let worst = 0;
    if (slavedI && m.qsI) {
      const ex = m.slipIx(y1);
      const ey = m.slipIy(y1);
      const dx = m.hintIx - uIx;
      const dy = m.hintIy - uIy;
      worst = Math.sqrt((ex * ex + ey * ey) * (dx * dx + dy * dy)) / 2.5;
    }
    if (slavedC && m.qsC) {
      const ex = m.slipCx(y1);
      const ey = m.slipCy(y1);
      const dx = m.hintCx - uCx;
      const dy = m.hintCy - uCy;
      const e = Math.sqrt((ex * ex + ey * ey) * (dx * dx + dy * dy)) / 2.5;
      if (e > worst) worst = e;
    }
    return worst;
  }

  /** Contact 0 (I) or 1 (C) slips on, held in direction (ux, uy) (CushionModel.frozenI). */
  private hold(contact: number, ux: number, uy: number): void {
    const m = this.model;
    if (contact === 0) {
      m.qsI = true;
      m.frozenI = true;
      m.hintIx = ux;
      m.hintIy = uy;
    } else {
      m.qsC = true;
      m.frozenC = true;
      m.hintCx = ux;
      m.hintCy = uy;
    }
  }

  /**
   * The impulse (per unit mass) over which a held slip's neglected rate could act: V, or in
   * restitution the impulse the work still needs at the current vy, if longer (a creep near
   * the both-rolling threshold can need a hundred times the usual impulse).
   */
  private holdSpan(): number {
    const vy = this.y[1]!;
    if (this.restitution && vy < 0) {
      const left = (this.y[5]! - this.wEnd) / (this.model.c * -vy);
      if (left > this.V) return left;
    }
    return this.V;
  }

  /** |rate| of contact 0 (I) or 1 (C)'s slip from a derivative vector k. */
  private rateSpeed(contact: number, k: Float64Array): number {
    const m = this.model;
    const rx = contact === 0 ? m.rateIx(k) : m.rateCx(k);
    const ry = contact === 0 ? m.rateIy(k) : m.rateCy(k);
    return Math.sqrt(rx * rx + ry * ry);
  }

  /** A slaved contact with slip (ex, ey), |slip| = r, follows its own direction again. */
  release(contact: number, ex: number, ey: number, r: number): void {
    const m = this.model;
    if (contact === 0) {
      m.qsI = false;
      m.frozenI = false;
    } else {
      m.qsC = false;
      m.frozenC = false;
    }
    if (r > m.epsSlip) {
      if (contact === 0) {
        m.refIx = ex / r;
        m.refIy = ey / r;
      } else {
        m.refCx = ex / r;
        m.refCy = ey / r;
      }
    }
  }

  /**
   * slavedStart's release of grown slaved slips, done before the inner loop is chosen: the
   * step after a slip's onset (a natural-roll impact's second step) then runs in the inner
   * loop instead of the general one. The same decision at the same state, so the same step.
   */
  private releaseGrown(): void {
    const m = this.model;
    const y = this.y;
    for (let contact = 0; contact < 2; contact++) {
      const qs = contact === 0 ? m.qsI : m.qsC;
      if (!qs || (contact === 0 ? m.modeI : m.modeC) !== SLIDE || (contact === 0 ? m.frozenI : m.frozenC)) continue;
      const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
      const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
      const r = Math.sqrt(ex * ex + ey * ey);
      if (!(r > QS_EXIT * this.V)) continue;
      const lam = contact === 0 ? m.slavedI(y) : m.slavedC(y);
      if (!(lam === lam) || lam > 0) this.release(contact, ex, ey, r);
    }
  }

  /**
   * At a step's start, for each slaved (quasi-static) contact: re-solve its direction, let it
   * follow its own direction again if it has grown past QS_EXIT, and return the impulse step
   * after which its slip would reach zero (Infinity if it does not shrink).
   */
  private slavedStart(step: number): number {
    const m = this.model;
    const y = this.y;
    let d = Infinity;
    for (let contact = 0; contact < 2; contact++) {
      const qs = contact === 0 ? m.qsI : m.qsC;
      if (!qs || (contact === 0 ? m.modeI : m.modeC) !== SLIDE) continue;
      if (contact === 0 ? m.frozenI : m.frozenC) {
        // A held slip stays held while its rates stay negligible (with a margin of ten).
        const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
        const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
        const k1 = this.rk.k1;
        if (this.rateSpeed(contact, k1) * this.holdSpan() > 10 * this.epsEv) this.release(contact, ex, ey, Math.sqrt(ex * ex + ey * ey));
        continue;
      }
      {
        // A slaved slip whose rates have vanished is held where it is (see slaveSmallSlips).
        const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
        const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
        const r = Math.sqrt(ex * ex + ey * ey);
        if (r > m.epsSlip && r <= QS_HOLD_RHO * this.V && this.rateSpeed(contact, this.rk.k1) * this.holdSpan() <= this.epsEv) {
          this.hold(contact, ex / r, ey / r);
          continue;
        }
      }
      const lam = contact === 0 ? m.slavedI(y) : m.slavedC(y);
      const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
      const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
      const r = Math.sqrt(ex * ex + ey * ey);
      if (!(lam === lam) || (lam > 0 && r > QS_EXIT * this.V)) {
        // Not available (C with I rolling) or grown: the slip follows its own direction.
        this.release(contact, ex, ey, r);
        continue;
      }
      if (contact === 0) {
        m.hintIx = m.ux;
        m.hintIy = m.uy;
      } else {
        m.hintCx = m.ux;
        m.hintCy = m.uy;
      }
      const along = ex * m.ux + ey * m.uy;
      if (lam < 0 && r > m.epsSlip) {
        // A shrinking slaved slip can only lose its component along u: when what is left
        // across u is as large (the slaved direction has turned as the state moved), the slip
        // is at its closest to zero. Within the event band it is zero (the rolling conditions
        // decide); otherwise it follows its own direction again.
        const px = ex - along * m.ux;
        const py = ey - along * m.uy;
        const across = Math.sqrt(px * px + py * py);
        if (!(along > across)) {
          if (r <= 10 * this.epsEv) {
            this.zeroNow |= contact === 0 ? 1 : 2;
          } else {
            this.release(contact, ex, ey, r);
          }
          continue;
        }
      }
      if (lam < 0 && along > 0) {
        const t = along / -lam;
        if (t < d) d = t;
      } else if (lam > 0) {
        // Growing: its exit from slaving is checked at step starts, so one step must not carry
        // it far past QS_EXIT (the error estimate does not see what slaving neglects).
        const t = (QS_GROW * this.V - r) / lam;
        if (t > 0 && t < d) d = t;
      }
    }
    return d < step ? d : step;
  }

  /**
   * After an accepted step: a slipping contact with a small slip whose direction already
   * follows the slaved one closely enough (δ × slip <= QS_FRACTION × tolerance) becomes slaved;
   * its offset absorbs the O(δ × slip) difference. True when a contact changed.
   */
  private slaveSmallSlips(tolV: number): boolean {
    const m = this.model;
    const y = this.y;
    let changed = false;
    for (let contact = 0; contact < 2; contact++) {
      const sliding = contact === 0 ? m.modeI === SLIDE && !m.qsI : m.modeC === SLIDE && !m.qsC;
      if (!sliding) continue;
      const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
      const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
      const r = Math.sqrt(ex * ex + ey * ey);
      if (r > m.epsSlip && r <= QS_HOLD_RHO * this.V && this.rateSpeed(contact, this.rk.k1) * this.holdSpan() <= this.epsEv) {
        // Its rates vanish along its own direction (friction at the both-rolling threshold): the
        // slip stays as it is, and is stiff however long it stays. Held in its direction, it
        // costs no steps; released as soon as its rates grow (slavedStart).
        this.hold(contact, ex / r, ey / r);
        changed = true;
        continue;
      }
      if (!(r <= QS_RHO * this.V) || !(r > 0)) continue;
      const lam = contact === 0 ? m.slavedI(y) : m.slavedC(y);
      if (!(lam === lam)) continue;
      // The slaved solution must agree with the slip's own motion: a slip that is shrinking
      // is never slaved to a direction in which it would grow (and the reverse), else a slip
      // about to reach zero and roll would slide off in a spurious direction.
      const k1 = this.rk.k1;
      const rate = contact === 0 ? ex * m.rateIx(k1) + ey * m.rateIy(k1) : ex * m.rateCx(k1) + ey * m.rateCy(k1);
      if ((lam > 0) !== (rate > 0)) continue;
      const dx = ex / r - m.ux;
      const dy = ey / r - m.uy;
      const delta = Math.sqrt(dx * dx + dy * dy);
      if (!(delta * r <= QS_FRACTION * tolV)) continue;
      // Slave it: its effective slip becomes r u* (offset absorbs r (u - u*)).
      if (contact === 0) {
        m.qsI = true;
        m.hintIx = m.ux;
        m.hintIy = m.uy;
        m.offIx += ex - r * m.ux;
        m.offIy += ey - r * m.uy;
      } else {
        m.qsC = true;
        m.hintCx = m.ux;
        m.hintCy = m.uy;
        m.offCx += ex - r * m.ux;
        m.offCy += ey - r * m.uy;
      }
      changed = true;
    }
    return changed;
  }

  /** Whether a slipping contact's slip is (within 10 event tolerances) zero at state ys. */
  private slipAtZero(ys: Float64Array): boolean {
    const m = this.model;
    const lim = 10 * this.epsEv;
    if (m.modeI === SLIDE) {
      const ex = m.slipIx(ys);
      const ey = m.slipIy(ys);
      if (ex * ex + ey * ey <= lim * lim) return true;
    }
    if (m.modeC === SLIDE) {
      const ex = m.slipCx(ys);
      const ey = m.slipCy(ys);
      if (ex * ex + ey * ey <= lim * lim) return true;
    }
    return false;
  }

  /**
   * The step shortened so that a sliding slip (ex, ey), |slip| = r, changing at (rx, ry) per unit
   * impulse neither passes zero (the step then aims at the zero) nor turns more than
   * TURN_MAX radians (a small slip turns fast, and the error estimate is blind to a turn much
   * faster than the step).
   */
  private limitBySlip(
    ex: number, ey: number, r: number, rx: number, ry: number, step: number, relax: number,
  ): number {
    const rate = (ex * rx + ey * ry) / r;
    if (rate < 0 && r <= -rate * step) step = -r / rate;
    const turn = Math.abs(rx * ey - ry * ex) / r;
    if (turn * step > TURN_MAX * r) step = TURN_MAX * r / turn;
    if (relax * step > RELAX_MAX * r) step = RELAX_MAX * r / relax;
    return step;
  }

  /**
   * The distance in impulse to the zero of contact 0's (I) or 1's (C) slip at the current state
   * and rates (rk.k1), when it slides on its own direction (not slaved) above the event band with
   * friction, and shrinks; Infinity otherwise (approachFactor).
   */
  private zeroDistanceOf(contact: number): number {
    const m = this.model;
    if (contact === 0 ? m.modeI !== SLIDE || m.qsI : m.modeC !== SLIDE || m.qsC) return Infinity;
    // Without friction at the contact, its slip's direction does not matter.
    if (!((contact === 0 ? m.muW : m.muS) > 0)) return Infinity;
    const y = this.y;
    const k = this.rk.k1;
    const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
    const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
    const r = Math.sqrt(ex * ex + ey * ey);
    if (!(r > m.epsSlip)) return Infinity;
    const rx = contact === 0 ? m.rateIx(k) : m.rateCx(k);
    const ry = contact === 0 ? m.rateIy(k) : m.rateCy(k);
    return zeroDistance(r, (ex * rx + ey * ry) / r);
  }

  /** |effective slip| of contact 0 (I) or 1 (C) at the current state. */
  private slipNorm(contact: number): number {
    const m = this.model;
    const y = this.y;
    const ex = contact === 0 ? m.slipIx(y) : m.slipCx(y);
    const ey = contact === 0 ? m.slipIy(y) : m.slipCy(y);
    return Math.sqrt(ex * ex + ey * ey);
  }

  /**
   * Slips of I (zI) and/or C (zC) are zero at y: record their residuals as offsets and decide
   * with the rolling conditions what each contact does. True when both now roll (every rate
   * is zero: the impact cannot progress).
   */
  private enterZero(zI: boolean, zC: boolean): boolean {
    const m = this.model;
    const slideI = m.modeI === SLIDE;
    const slideC = m.modeC === SLIDE;
    const both = this.decideZero(zI, zC);
    this.zeroed = true;
    if ((slideI && m.modeI === STICK) || (slideC && m.modeC === STICK)) this.stuck = true;
    return both;
  }

  /** enterZero's decision (the rolling conditions at the zero). */
  private decideZero(zI: boolean, zC: boolean): boolean {
    const m = this.model;
    const y = this.y;
    if (zI) {
      m.offIx = y[0]! + m.s * y[3]! - m.c * y[4]!;
      m.offIy = -m.s * y[1]! + y[2]!;
    }
    if (zC) {
      m.offCx = y[0]! - y[3]!;
      m.offCy = y[1]! + y[2]!;
    }
    const atI = zI || m.modeI === STICK;
    const atC = zC || m.modeC === STICK;
    if (atI && atC) return m.onsetBoth(y);
    if (zC) m.onsetC(y);
    else m.onsetI(y);
    return false;
  }

  /**
   * The next step from the step control's proposal and the approach factor of the step just
   * taken (approachFactor): scaled by it, unless a slip has reached its zero since (enterZero),
   * which ends its approach. After a sliding contact started to roll there (stuck), at least
   * RESTART_FRACTION of stepFree.
   * The approach to the zero shrank the steps to a fraction of the distance left, down to the
   * event tolerance; the rolling branch after it is smooth, and growing back from there by the
   * step control's factor of at most 5 a step took 4-8 steps on the near head-on impacts without
   * spin. The error test cuts a restart that is too long (by up to 5 a rejection).
   */
  private afterZero(proposal: number, approach: number): number {
    if (!this.zeroed) return proposal * approach;
    this.zeroed = false;
    if (!this.stuck) return proposal; // (a slip left its zero: a new start, not an approach)
    this.stuck = false;
    const restart = RESTART_FRACTION * this.stepFree;
    return proposal < restart ? restart : proposal;
  }

  /** Whether every sliding contact follows its own direction with a slip above QS_RHO of the speed. */
  private slipsClear(): boolean {
    const m = this.model;
    const lim = QS_RHO * this.V;
    if (m.modeI === SLIDE && (m.qsI || !(this.slipNorm(0) > lim))) return false;
    if (m.modeC === SLIDE && (m.qsC || !(this.slipNorm(1) > lim))) return false;
    return true;
  }

  /** The stuck contact needs more than its friction cone: it starts to slip. */
  private leaveStick(): void {
    const m = this.model;
    const y = this.y;
    m.stickMargin(y); // fills the rolling frictions at y
    if (m.modeI === STICK) {
      const n = Math.sqrt(m.gx * m.gx + m.gy * m.gy);
      m.modeI = SLIDE;
      m.qsI = true;
      m.frozenI = false;
      m.offIx = y[0]! + m.s * y[3]! - m.c * y[4]!;
      m.offIy = -m.s * y[1]! + y[2]!;
      if (n > 0) {
        m.hintIx = -m.gx / n;
        m.hintIy = -m.gy / n;
      }
    } else {
      const n = Math.sqrt(m.hx * m.hx + m.hy * m.hy);
      m.modeC = SLIDE;
      m.qsC = true;
      m.frozenC = false;
      m.offCx = y[0]! - y[3]!;
      m.offCy = y[1]! + y[2]!;
      if (n > 0) {
        m.hintCx = -m.hx / n;
        m.hintCy = -m.hy / n;
      }
    }
  }

  /**
   * vy came back to zero in restitution (a stall) at y with a sliding contact's slip within
   * STALL_ZERO event tolerances of zero: that slip is taken as zero and the rolling conditions
   * decide again (enterZero: a contact's mode, or the direction in which a slip leaves zero, may
   * change). True (the integration goes on) when the impulse then pushes the ball out, at most
   * REDECISIONS times an impact. With friction a hair below the both-rolling threshold
   * cos θ / (1 + sin θ), a slip closing on zero together with vy was left sliding at 1e-7 to
   * 4e-7 of the speed, vy came back to zero and the impact stalled where the reference rebounds
   * slowly (up to 5.9e-2 V0 off; docs/cushion.md, Limits); decided at that zero, the ball leaves.
   */
  private redecideAtStall(): boolean {
    if (this.redecisions >= REDECISIONS) return false;
    this.redecisions++;
    const m = this.model;
    const zI = m.modeI === SLIDE && this.slipNorm(0) <= STALL_ZERO * this.epsEv;
    const zC = m.modeC === SLIDE && this.slipNorm(1) <= STALL_ZERO * this.epsEv;
    if (!zI && !zC) return false;
    if (this.enterZero(zI, zC)) return false;
    m.derivative(this.y, this.rk.k1);
    return this.rk.k1[1]! < 0;
  }

  /** Both contacts roll: nothing changes any more, so restitution cannot finish. */
  private finishStalled(): void {
    this.outcome = 'stalled';
    this.y[1] = 0;
  }

  /** Event function at fraction theta of the last step (> 0 before the event). */
  private eventAt(kind: number, theta: number): number {
    const rk = this.rk;
    if (kind === EV_VY_BACK) return -rk.denseAt(theta, 1);
    rk.denseAll(theta, this.kd);
    return -this.model.stickMargin(this.kd);
  }

  /**
   * The first theta in [lo, hi] where the event function reaches zero (it is > 0 at lo and
   * <= 0 at hi, or the event is at lo). vy and the work are variables of the continuous
   * extension: Newton's method on it (cushion-dense.ts). The others (vy back at zero, a stuck
   * contact leaving its cone): Illinois-modified regula falsi, at most 100 iterations,
   * returning the bracket's event side.
   */
  private root(kind: number, target: number, lo: number, hi: number): number {
    if (kind === EV_VY) return denseRoot(this.rk.dense, 1, 0, lo, hi);
    if (kind === EV_WORK) return denseRoot(this.rk.dense, 5, target, lo, hi);
    let flo = this.eventAt(kind, lo);
    if (!(flo > 0)) return lo;
    let fhi = this.eventAt(kind, hi);
    if (fhi > 0) return hi;
    let side = 0;
    for (let i = 0; i < 100 && fhi !== 0 && hi - lo > 1e-15; i++) {
      let x = lo + (hi - lo) * (flo / (flo - fhi));
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      const fx = this.eventAt(kind, x);
      if (fx > 0) {
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
    }
    return hi;
  }

  /** Appends samples of the last step (fractions up to `upTo`) when tracing. */
  private recordTrace(step: number, upTo: number): void {
    const trace = this.trace;
    if (trace === null) return;
    const n = step === 0 ? 1 : 8;
    for (let j = step === 0 ? 0 : 1; j <= n; j++) {
      const theta = step === 0 ? 0 : (upTo * j) / n;
      if (step === 0) copy6(this.y, this.ye);
      else this.rk.denseAll(theta, this.ye);
      trace.push(this.samplePoint(this.p + theta * step, this.ye));
    }
  }

  private samplePoint(p: number, y: Float64Array): CushionTracePoint {
    const m = this.model;
    const R = this.R;
    return {
      P: p * this.M,
      vx: y[0]!,
      vy: y[1]!,
      wx: y[2]! / R,
      wy: y[3]! / R,
      wz: y[4]! / R,
      xI: y[0]! + m.s * y[3]! - m.c * y[4]!,
      yI: -m.s * y[1]! + y[2]!,
      xC: y[0]! - y[3]!,
      yC: y[1]! + y[2]!,
      W: y[5]! * this.M,
      stickI: m.modeI === STICK,
      stickC: m.modeC === STICK,
    };
  }
}

function copy6(from: Float64Array, to: Float64Array): void {
  to[0] = from[0]!;
  to[1] = from[1]!;
  to[2] = from[2]!;
  to[3] = from[3]!;
  to[4] = from[4]!;
  to[5] = from[5]!;
}
