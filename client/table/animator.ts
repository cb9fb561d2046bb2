// Plays an outcome on a table view from its closed-form paths (sampleOutcome), one frame per
// display refresh: the balls turned by their spin, a pocketed ball dropping into its pocket. The
// playback rate can change while it plays and it can skip to the end; its last frame is always the
// outcome's end. Keeps the frame times so they can be measured.
import { sampleOutcome, type BallAtTime, type Outcome } from '../../shared/physics/index.ts';
import type { DrawnBall } from './draw.ts';
import type { TableView } from './view.ts';

/** Frame-to-frame times (ms) of every animation on the page, for measurement (window.baizeFrames). */
const frames: number[] = [];
(globalThis as { baizeFrames?: number[] }).baizeFrames = frames;

/** How long a pocketed ball takes to drop out of sight (s of the outcome). */
export const DROP_TIME = 0.3;

interface Drop {
  id: string;
  t: number;
  /** Where it fell from, and the pocket's centre. */
  x: number;
  y: number;
  px: number;
  py: number;
}

export class Animator {
  private raf = 0;
  private done: (() => void) | undefined;
  private outcome: Outcome | null = null;
  private drops: Drop[] = [];
  /** The animation's last moment: the outcome's end, or a later ball's drop out of sight. */
  private end = 0;
  private t = 0;
  private rate = 1;
  /** The outcome time at the wall-clock moment `anchorNow` (ms); t runs from there at `rate`. */
  private anchorT = 0;
  private anchorNow = 0;
  /** The last frame's samples and time, for turning the balls between frames. */
  private prev: BallAtTime[] = [];
  private prevT = 0;
  /** Ball ids in the order they went into pockets, over every outcome played here (latest last). */
  readonly pocketOrder: string[] = [];

  constructor(private readonly view: TableView) {}

  get playing(): boolean {
    return this.raf !== 0;
  }

  /** The outcome time shown now (s), at most its duration. */
  get time(): number {
    return this.outcome ? Math.min(this.t, this.outcome.duration) : 0;
  }

  /** The playback rate: 1 is real time. */
  get speed(): number {
    return this.rate;
  }

  /** Animates the outcome at `speed` times real time from `from` seconds; resolves at its end (or when stopped or skipped). */
  play(outcome: Outcome, speed = 1, from = 0): Promise<void> {
    this.stop();
    this.outcome = outcome;
    this.rate = speed;
    this.t = from;
    for (const e of outcome.events) {
      if (e.kind !== 'pocket') continue;
      const id = e.balls[0]!;
      const k = this.pocketOrder.indexOf(id);
      if (k >= 0) this.pocketOrder.splice(k, 1);
      this.pocketOrder.push(id);
    }
    if (document.hidden) {
      // Nobody is looking: show where the balls end, at once.
      this.drawEnd();
      return Promise.resolve();
    }
    this.drops = drops(outcome, this.view.spec.pockets);
    this.end = Math.max(outcome.duration, ...this.drops.map((d) => d.t + DROP_TIME));
    this.prev = sampleOutcome(outcome, from);
    this.prevT = from;
    return new Promise((resolve) => {
      this.done = resolve;
      this.anchorT = from;
      this.anchorNow = performance.now();
      let last = this.anchorNow;
      const step = (now: number) => {
        frames.push(now - last);
        if (frames.length > 10_000) frames.splice(0, 5_000);
        last = now;
        this.t = this.anchorT + ((now - this.anchorNow) / 1000) * this.rate;
        if (this.t >= this.end) {
          this.drawEnd();
          this.finish();
          return;
        }
        this.drawAt(this.t);
        this.raf = requestAnimationFrame(step);
      };
      this.raf = requestAnimationFrame(step);
    });
  }

  /** Changes the playback rate (1, 2, 4...) from the time shown now. */
  setSpeed(speed: number): void {
    if (!(speed > 0)) return;
    if (this.playing) {
      const now = performance.now();
      this.anchorT = this.anchorT + ((now - this.anchorNow) / 1000) * this.rate;
      this.anchorNow = now;
    }
    this.rate = speed;
  }

  /** Shows the outcome's end at once and ends the animation (its promise resolves). */
  skipToEnd(): void {
    if (!this.playing) return;
    cancelAnimationFrame(this.raf);
    this.drawEnd();
    this.finish();
  }

  stop(): void {
    if (this.raf !== 0) cancelAnimationFrame(this.raf);
    this.finish();
  }

  /** One frame at time t: balls turned by their spin since the last frame, drops in progress. */
  private drawAt(t: number): void {
    const outcome = this.outcome!;
    const now = sampleOutcome(outcome, Math.min(t, outcome.duration));
    const dt = Math.min(t, outcome.duration) - this.prevT;
    const turn = this.view.orientations;
    now.forEach((b, i) => {
      const p = this.prev[i];
      // The mean of the spins at the two frames, turned through exactly (orientation.ts).
      if (p && dt > 0) turn.spin(b.id, (p.wx + b.wx) / 2, (p.wy + b.wy) / 2, (p.wz + b.wz) / 2, dt);
    });
    this.prev = now;
    this.prevT = Math.min(t, outcome.duration);
    const balls: DrawnBall[] = [];
    for (const d of this.drops) {
      if (t < d.t || t >= d.t + DROP_TIME) continue;
      const u = (t - d.t) / DROP_TIME;
      const k = u * u * (3 - 2 * u);
      balls.push({ id: d.id, x: d.x + (d.px - d.x) * k, y: d.y + (d.py - d.y) * k, sink: u });
    }
    for (const b of now) if (b.motion !== 'pocketed') balls.push({ id: b.id, x: b.x, y: b.y });
    this.view.draw(balls);
  }

  /** The outcome's end exactly: where the balls rest, none of the pocketed ones. */
  private drawEnd(): void {
    const outcome = this.outcome!;
    this.t = outcome.duration;
    this.view.draw(sampleOutcome(outcome, outcome.duration).filter((b) => b.motion !== 'pocketed'));
  }

  private finish(): void {
    this.raf = 0;
    const done = this.done;
    this.done = undefined;
    done?.();
  }
}

/** Each pocketed ball's fall: from where it went down to its pocket's centre. */
function drops(outcome: Outcome, pockets: readonly { id: string; x: number; y: number }[]): Drop[] {
  const out: Drop[] = [];
  const path = new Map(outcome.paths.map((p) => [p.id, p.segments]));
  for (const e of outcome.events) {
    if (e.kind !== 'pocket') continue;
    const id = e.balls[0]!;
    const seg = path.get(id)?.find((s) => s.motion === 'pocketed');
    const pocket = pockets.find((p) => p.id === e.pocket);
    if (!seg || !pocket) continue;
    out.push({ id, t: e.t, x: seg.x, y: seg.y, px: pocket.x, py: pocket.y });
  }
  return out;
}
