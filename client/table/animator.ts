// Plays an outcome on a table view from its closed-form paths (sampleOutcome), one frame per
// display refresh, and keeps the frame times so they can be measured.
import { sampleOutcome, type Outcome } from '../../shared/physics/index.ts';
import type { TableView } from './view.ts';

/** Frame-to-frame times (ms) of every animation on the page, for measurement (window.baizeFrames). */
const frames: number[] = [];
(globalThis as { baizeFrames?: number[] }).baizeFrames = frames;

export class Animator {
  private raf = 0;
  private done: (() => void) | undefined;

  constructor(private readonly view: TableView) {}

  get playing(): boolean {
    return this.raf !== 0;
  }

  /** Animates the outcome at `speed` times real time from `from` seconds; resolves at its end (or when stopped). */
  play(outcome: Outcome, speed = 1, from = 0): Promise<void> {
    this.stop();
    if (document.hidden) {
      // Nobody is looking: show where the balls end, at once.
      this.view.draw(sampleOutcome(outcome, outcome.duration).filter((b) => b.motion !== 'pocketed'));
      return Promise.resolve();
    }
    return new Promise((resolve) => {
      this.done = resolve;
      const start = performance.now();
      let last = start;
      const step = (now: number) => {
        frames.push(now - last);
        if (frames.length > 10_000) frames.splice(0, 5_000);
        last = now;
        const t = Math.min(outcome.duration, from + ((now - start) / 1000) * speed);
        this.view.draw(sampleOutcome(outcome, t).filter((b) => b.motion !== 'pocketed'));
        if (t < outcome.duration) this.raf = requestAnimationFrame(step);
        else this.finish();
      };
      this.raf = requestAnimationFrame(step);
    });
  }

  stop(): void {
    if (this.raf !== 0) cancelAnimationFrame(this.raf);
    this.finish();
  }

  private finish(): void {
    this.raf = 0;
    const done = this.done;
    this.done = undefined;
    done?.();
  }
}
