// The table simulation: one loop that pops the earliest predicted event, applies it to the balls
// involved, and predicts again only for them (detect.ts says when, ball-collision.ts and the
// cushion kernel say what, cloth-motion.ts moves the balls in between). Balls at rest cost nothing
// and effort follows events: nothing steps with the clock.
import { type BallSample, type BallState, type Motion } from './ball-state.ts';
import { collideBalls, type BallBallParams } from './ball-collision.ts';
import { emptySample, sampleAt, settle, startSegment, type ClothParams } from './cloth-motion.ts';
import { impactKind, restAgainstCushion, settlePair, stopBoth, TC_TIME } from './contact-policy.ts';
import { CushionKernel } from './cushion/index.ts';
import type { CushionParams } from './cushion/index.ts';
import { arcTime, ballBallTime, boxesOverlap, CONTACT_SPEED, pocketTime, segmentTime, sweptBox, type Path } from './detect.ts';
import { EventQueue, Kind, type Prediction } from './event-queue.ts';
import { hashFinalState } from './hash.ts';
import type { FinalBall, Outcome, PathSegment, Scene, Shot, SimEvent, SimOptions } from './sim-types.ts';
import { strikeBall } from './strike.ts';
import { clothParamsOf, type TableSpec } from './tables.ts';
import { validateOptions, validateScene, validateShot } from './validate-input.ts';

/** Events per ball beyond which the loop is broken, with an error, never a silent answer. */
const EVENTS_PER_BALL_LIMIT = 2000;

/** The bounding boxes of a table's cushions and pockets, built once per table. */
const BOXES = new WeakMap<TableSpec, { cushions: Float64Array[]; pockets: Float64Array[] }>();
function tableBoxes(table: TableSpec): { cushions: Float64Array[]; pockets: Float64Array[] } {
  let boxes = BOXES.get(table);
  if (!boxes) {
    boxes = {
      cushions: table.cushions.map((c) =>
        c.kind === 'segment'
          ? new Float64Array([Math.min(c.ax, c.bx), Math.min(c.ay, c.by), Math.max(c.ax, c.bx), Math.max(c.ay, c.by)])
          : new Float64Array([c.cx - c.r, c.cy - c.r, c.cx + c.r, c.cy + c.r]),
      ),
      pockets: table.pockets.map((p) => new Float64Array([p.x - p.r, p.y - p.r, p.x + p.r, p.y + p.r])),
    };
    BOXES.set(table, boxes);
  }
  return boxes;
}

class Simulation {
  readonly balls: BallState[];
  readonly queue = new EventQueue();
  readonly events: SimEvent[] = [];
  readonly segments: PathSegment[][];
  readonly cloth: ClothParams;
  readonly ballParams: BallBallParams;
  readonly elasticParams: BallBallParams;
  readonly plasticParams: BallBallParams;
  private readonly lastImpact: number[];
  /** When each ball's own next event (motion change, cushion, pocket) is due; Infinity at rest. */
  private readonly nextOwn: number[];
  /** Impacts of each ball at the instant of its last impact. */
  private readonly impactsNow: number[];
  /** When each ball was last in a pressed contact (see onBall). */
  private readonly lastPress: number[];
  readonly R: number;
  private readonly sa: BallSample = emptySample();
  private readonly sb: BallSample = emptySample();
  private readonly scratch: BallSample = emptySample();
  /** Each ball's path as seen from the time and segment it was last computed for (see pathOf). */
  private readonly paths: Path[];
  private readonly pathTime: number[];
  private readonly pathVersion: number[];
  private readonly boxA = new Float64Array(4);
  private readonly boxB = new Float64Array(4);
  private readonly cushionBoxes: Float64Array[];
  private readonly pocketBoxes: Float64Array[];
  /** One cushion solver for the shot's impacts. */
  private readonly cushion = new CushionKernel();

  constructor(
    readonly table: TableSpec,
    scene: Scene,
    readonly rootTol: number,
    readonly cushionTol: SimOptions['cushionTolerance'],
    /** The cushion kernel's constants: the table's, or the caller's (SimOptions.cushion). */
    readonly cushionParams: CushionParams,
  ) {
    this.R = table.ballRadius;
    this.cloth = clothParamsOf(table);
    this.ballParams = { R: this.R, ...table.ballBall };
    this.elasticParams = { ...this.ballParams, restitution: 1 };
    this.plasticParams = { ...this.ballParams, restitution: 0 };
    this.lastImpact = scene.balls.map(() => -Infinity);
    this.nextOwn = scene.balls.map(() => Infinity);
    this.impactsNow = scene.balls.map(() => 0);
    this.lastPress = scene.balls.map(() => -Infinity);
    this.balls = scene.balls.map((b, index) => ({
      id: b.id,
      index,
      motion: 'rest' as Motion,
      t0: 0,
      x: b.x === 0 ? 0 : b.x,
      y: b.y === 0 ? 0 : b.y,
      vx: 0,
      vy: 0,
      wx: 0,
      wy: 0,
      wz: 0,
      ax: 0,
      ay: 0,
      tEnd: Infinity,
      version: 0,
      pocket: undefined,
    }));
    this.segments = this.balls.map(() => []);
    this.paths = this.balls.map(() => ({ x: 0, y: 0, vx: 0, vy: 0, ax: 0, ay: 0 }));
    this.pathTime = this.balls.map(() => Number.NaN);
    this.pathVersion = this.balls.map(() => -1);
    const boxes = tableBoxes(table);
    this.cushionBoxes = boxes.cushions;
    this.pocketBoxes = boxes.pockets;
  }

  private record(b: BallState): void {
    this.segments[b.index]!.push({ t0: b.t0, motion: b.motion, x: b.x, y: b.y, vx: b.vx, vy: b.vy, wx: b.wx, wy: b.wy, wz: b.wz, ax: b.ax, ay: b.ay });
  }

  /** Ends b's segment at t with the state s and starts the next one. */
  private restart(b: BallState, t: number, s: BallSample): void {
    startSegment(b, t, s, this.cloth);
    this.record(b);
  }

  /** b's path relative to time t, computed once per ball, time and segment. */
  private pathOf(b: BallState, t: number): Path {
    const out = this.paths[b.index]!;
    if (this.pathTime[b.index] === t && this.pathVersion[b.index] === b.version) return out;
    this.pathTime[b.index] = t;
    this.pathVersion[b.index] = b.version;
    // sampleAt gives a ball that does not translate zero velocity, and its segment zero acceleration.
    const s = sampleAt(b, t - b.t0, this.cloth, this.sa);
    out.x = s.x;
    out.y = s.y;
    out.vx = s.vx;
    out.vy = s.vy;
    out.ax = b.ax;
    out.ay = b.ay;
    return out;
  }

  private translating(b: BallState): boolean {
    return b.motion === 'sliding' || b.motion === 'rolling';
  }

  /** Predicts b's own next event: a change of motion, a cushion or a pocket. */
  private predictOwn(b: BallState, t: number): void {
    this.nextOwn[b.index] = Infinity;
    if (b.motion === 'rest' || b.motion === 'pocketed') return;
    let best = b.tEnd - t;
    let kind: Kind = Kind.Motion;
    let target = -1;
    if (this.translating(b)) {
      const p = this.pathOf(b, t);
      const H = best;
      const box = sweptBox(p, H, this.R, this.boxA);
      const cushions = this.table.cushions;
      for (let i = 0; i < cushions.length; i++) {
        if (!boxesOverlap(box, this.cushionBoxes[i]!)) continue;
        const c = cushions[i]!;
        // Searched only up to the earliest event found so far: nothing later can win.
        const tau = c.kind === 'segment' ? segmentTime(p, c, this.R, best, this.rootTol) : arcTime(p, c, this.R, best, this.rootTol);
        if (tau < best || (tau === best && kind === Kind.Cushion && i < target)) {
          best = tau;
          kind = Kind.Cushion;
          target = i;
        }
      }
      const pocketBox = sweptBox(p, H, 0, this.boxB);
      const pockets = this.table.pockets;
      for (let i = 0; i < pockets.length; i++) {
        if (!boxesOverlap(pocketBox, this.pocketBoxes[i]!)) continue;
        const tau = pocketTime(p, pockets[i]!, best, this.rootTol);
        if (tau <= best) {
          best = tau;
          kind = Kind.Pocket;
          target = i;
        }
      }
    }
    this.nextOwn[b.index] = t + best;
    this.queue.push({ t: t + best, kind, a: b.index, b: target, versionA: b.version, versionB: 0 });
  }

  /** Predicts when a and b meet, if before either changes its motion. */
  private predictPair(a: BallState, b: BallState, t: number): void {
    const ma = this.translating(a);
    const mb = this.translating(b);
    if (!ma && !mb) return;
    if (a.motion === 'pocketed' || b.motion === 'pocketed') return;
    // Not past either ball's own next event: there its path changes and the pair is predicted again.
    const H = Math.min(this.nextOwn[a.index]!, this.nextOwn[b.index]!) - t;
    if (!(H >= 0)) return;
    const pa = this.pathOf(a, t);
    const pb = this.pathOf(b, t);
    if (!boxesOverlap(sweptBox(pa, H, this.R, this.boxA), sweptBox(pb, H, this.R, this.boxB))) return;
    const tau = ballBallTime(pa, pb, this.R, H, this.rootTol);
    if (tau === Infinity) return;
    const [first, second] = a.index < b.index ? [a, b] : [b, a];
    this.queue.push({ t: t + tau, kind: Kind.Ball, a: first.index, b: second.index, versionA: first.version, versionB: second.version });
  }

  private predictAround(changed: readonly BallState[], t: number): void {
    for (const b of changed) this.predictOwn(b, t);
    for (const b of changed) {
      for (const other of this.balls) {
        if (other === b) continue;
        // A pair of two changed balls is predicted once, from the lower index.
        if (changed.includes(other) && other.index < b.index) continue;
        this.predictPair(b, other, t);
      }
    }
  }

  /** Counts b's impacts at the instant t (1 for the first). */
  private countImpact(b: BallState, t: number): number {
    const n = this.lastImpact[b.index] === t ? this.impactsNow[b.index]! + 1 : 1;
    this.impactsNow[b.index] = n;
    return n;
  }

  private stale(p: Prediction): boolean {
    if (this.balls[p.a]!.version !== p.versionA) return true;
    return p.kind === Kind.Ball && this.balls[p.b]!.version !== p.versionB;
  }

  strike(shot: Shot): void {
    const cue = this.balls.find((b) => b.id === shot.ball)!;
    const s = sampleAt(cue, 0, this.cloth, emptySample());
    strikeBall(shot.heading, shot.speed, shot.side, shot.top, this.R, s);
    for (const b of this.balls) if (b !== cue) this.record(b);
    this.restart(cue, 0, s);
    this.predictAround([cue], 0);
  }

  run(): number {
    const limit = EVENTS_PER_BALL_LIMIT * this.balls.length;
    let last = 0;
    for (let p = this.queue.pop(); p; p = this.queue.pop()) {
      if (this.stale(p)) continue;
      if (this.events.length >= limit) {
        throw new Error(`simulation did not settle: ${this.events.length} events by t = ${p.t} s (a bug: please report the scene and shot)`);
      }
      const t = p.t;
      last = t;
      const a = this.balls[p.a]!;
      switch (p.kind) {
        case Kind.Motion:
          this.onMotion(a, t);
          break;
        case Kind.Pocket:
          this.onPocket(a, p.b, t);
          break;
        case Kind.Ball:
          this.onBall(a, this.balls[p.b]!, t);
          break;
        case Kind.Cushion:
          this.onCushion(a, p.b, t);
          break;
      }
    }
    return last;
  }

  private onMotion(b: BallState, t: number): void {
    const from = b.motion;
    const s = sampleAt(b, t - b.t0, this.cloth, this.sa);
    this.restart(b, t, s);
    this.events.push({ t, kind: 'motion', balls: [b.id], from, to: b.motion });
    this.predictAround([b], t);
  }

  private onPocket(b: BallState, index: number, t: number): void {
    const pocket = this.table.pockets[index]!;
    const s = sampleAt(b, t - b.t0, this.cloth, this.sa);
    b.t0 = t;
    b.x = s.x;
    b.y = s.y;
    b.vx = b.vy = b.wx = b.wy = b.wz = b.ax = b.ay = 0;
    b.motion = 'pocketed';
    b.tEnd = Infinity;
    b.pocket = pocket.id;
    b.version++;
    this.record(b);
    this.events.push({ t, kind: 'pocket', balls: [b.id], pocket: pocket.id });
  }

  private onBall(a: BallState, b: BallState, t: number): void {
    const sa = sampleAt(a, t - a.t0, this.cloth, this.sa);
    const sb = sampleAt(b, t - b.t0, this.cloth, this.sb);
    const nx0 = sb.x - sa.x;
    const ny0 = sb.y - sa.y;
    const d = Math.sqrt(nx0 * nx0 + ny0 * ny0);
    const speed = ((sa.vx - sb.vx) * nx0 + (sa.vy - sb.vy) * ny0) / d;
    // TC model: a ball struck again within TC_TIME of its last impact bounces elastically.
    const rapid = t - this.lastImpact[a.index]! < TC_TIME || t - this.lastImpact[b.index]! < TC_TIME;
    const kind = impactKind(Math.max(this.countImpact(a, t), this.countImpact(b, t)), rapid);
    if (kind === 'wedged') stopBoth(sa, sb);
    else collideBalls(sa, sb, kind === 'plastic' ? this.plasticParams : kind === 'elastic' ? this.elasticParams : this.ballParams);
    this.lastImpact[a.index] = t;
    this.lastImpact[b.index] = t;
    settle(sa, this.cloth);
    settle(sb, this.cloth);
    settlePair(sa, sb, nx0 / d, ny0 / d, this.cloth, this.scratch);
    if (!(speed > CONTACT_SPEED)) {
      // A pressed contact again at the same instant: the ball is wedged in a cluster whose pair
      // locks undo each other (a ball pressed from two sides). Both stop; only energy is lost.
      if (this.lastPress[a.index] === t || this.lastPress[b.index] === t) stopBoth(sa, sb);
      this.lastPress[a.index] = t;
      this.lastPress[b.index] = t;
    }
    this.restart(a, t, sa);
    this.restart(b, t, sb);
    this.events.push({ t, kind: 'ball', balls: [a.id, b.id], speed });
    this.predictAround([a, b], t);
  }

  private onCushion(b: BallState, index: number, t: number): void {
    const cushion = this.table.cushions[index]!;
    const s = sampleAt(b, t - b.t0, this.cloth, this.sa);
    // n: unit normal into the cushion at the contact.
    let nx: number;
    let ny: number;
    if (cushion.kind === 'segment') {
      nx = cushion.nx;
      ny = cushion.ny;
    } else {
      nx = cushion.cx - s.x;
      ny = cushion.cy - s.y;
      const d = Math.sqrt(nx * nx + ny * ny);
      nx /= d;
      ny /= d;
    }
    // The cushion frame (Mathavan): y = n into the cushion, x = (n_y, -n_x), z up: right-handed.
    const vxf = s.vx * ny - s.vy * nx;
    const vyf = s.vx * nx + s.vy * ny;
    const wxf = s.wx * ny - s.wy * nx;
    const wyf = s.wx * nx + s.wy * ny;
    // A cushion radius given per call (options.cushion.R) is the model's: the spins go in and out
    // at the same surface speeds R ω, so that the ball's energy on the cloth (its own R) is the
    // model's, which never grows.
    const k = this.cushionParams.R === this.R ? 1 : this.R / this.cushionParams.R;
    const input = k === 1 ? { vx: vxf, vy: vyf, wx: wxf, wy: wyf, wz: s.wz } : { vx: vxf, vy: vyf, wx: wxf * k, wy: wyf * k, wz: s.wz * k };
    // The table's restitution falling with the normal speed (CushionSpec.restitutionSlope), if set.
    const slope = this.table.cushion.restitutionSlope;
    const params = slope === undefined || slope === 0
      ? this.cushionParams
      : { ...this.cushionParams, ee: Math.min(1, Math.max(0, this.cushionParams.ee - slope * vyf)) };
    let out: ReturnType<CushionKernel['rebound']>;
    try {
      out = this.cushion.rebound(input, params, { tolerance: this.cushionTol });
    } catch (err) {
      throw new Error(`cushion impact of ball "${b.id}" on ${cushion.name} at t = ${t} s failed: ${(err as Error).message}; input ${JSON.stringify(input)}, params ${JSON.stringify(params)}`);
    }
    s.vx = out.vx * ny + out.vy * nx;
    s.vy = -out.vx * nx + out.vy * ny;
    if (k !== 1) {
      out.wx /= k;
      out.wy /= k;
      out.wz /= k;
    }
    s.wx = out.wx * ny + out.wy * nx;
    s.wy = -out.wx * nx + out.wy * ny;
    s.wz = out.wz;
    // A rebound too weak to leave the cushion against the cloth's pull becomes a resting contact.
    const away = -(s.vx * nx + s.vy * ny);
    restAgainstCushion(s, nx, ny, away, this.cloth, this.scratch);
    this.restart(b, t, s);
    this.events.push({ t, kind: 'cushion', balls: [b.id], cushion: cushion.name, speed: vyf });
    this.predictAround([b], t);
  }

  finish(duration: number): Outcome {
    const balls: FinalBall[] = this.balls.map((b) => {
      const s = sampleAt(b, Math.max(0, duration - b.t0), this.cloth, this.sa);
      const x = b.motion === 'pocketed' ? b.x : s.x;
      const y = b.motion === 'pocketed' ? b.y : s.y;
      const fb: FinalBall = { id: b.id, x: x === 0 ? 0 : x, y: y === 0 ? 0 : y, pocketed: b.motion === 'pocketed' };
      return b.pocket === undefined ? fb : { ...fb, pocket: b.pocket };
    });
    return {
      table: this.table.name,
      balls,
      events: this.events,
      duration,
      hash: hashFinalState(balls, duration, this.events.length),
      paths: this.balls.map((b, i) => ({ id: b.id, segments: this.segments[i]! })),
    };
  }
}

/**
 * Plays a shot on a scene of balls at rest and returns where they end, every event in time order,
 * the time until all rest, a hash of the final state and every ball's path. Bad input throws a
 * SimulationInputError (a RangeError) naming the problem before anything is simulated; a tip
 * offset beyond half the radius throws a MiscueError. `options.cushion` replaces constants of the
 * cushion impacts only (see SimOptions).
 */
export function simulate(scene: Scene, shot: Shot, options?: SimOptions): Outcome {
  return simulateOn(validateScene(scene), scene, shot, options);
}

/**
 * simulate() on a table spec of the caller's: the registered table's geometry with other physical
 * constants (cloth, ball-ball, cushion), for fitting the constants to real shots (npm run
 * fidelity). The scene is checked against its registered table, whose geometry this must share.
 */
export function simulateOn(table: TableSpec, scene: Scene, shot: Shot, options?: SimOptions): Outcome {
  validateScene(scene);
  validateShot(scene, shot);
  const { rootTolerance, cushionTolerance, cushionParams } = validateOptions(options, table);
  const sim = new Simulation(table, scene, rootTolerance, cushionTolerance, cushionParams);
  sim.strike(shot);
  const duration = sim.run();
  return sim.finish(duration);
}
