// The pace of a shot's animation, for anyone watching it: a "Fast forward" button (and the F key)
// steps x1 → x2 → x4 → the end. It changes only what is shown: the shot, its hash and the game are
// the same. The animation is restarted from the time it has reached at the new speed
// (Animator.play(outcome, speed, from)), and the shot's sounds follow it.
import type { Outcome } from '../../shared/physics/index.ts';
import { h } from '../dom.ts';
import { soundSchedule, type SoundCue, type SoundPlayer } from './sound.ts';

/** What plays an outcome: the Animator. */
export interface Playback {
  play(outcome: Outcome, speed?: number, from?: number): Promise<void>;
}

/** The next pace after `speed`: x2, x4, then the end. */
export function nextPace(speed: number): number | 'end' {
  return speed < 2 ? 2 : speed < 4 ? 4 : 'end';
}

const label = (next: number | 'end') => (next === 'end' ? 'Fast forward to the end' : `Fast forward ×${next}`);

interface Playing {
  readonly outcome: Outcome;
  readonly sounds: readonly SoundCue[];
  readonly resolve: () => void;
  speed: number;
  /** The animation's time (s) when it was (re)started, and the page's clock then (ms). */
  from: number;
  at: number;
  run: number;
}

export class Pace {
  /** Shown only while a shot animates. */
  readonly button: HTMLButtonElement;
  private current: Playing | null = null;
  private runs = 0;
  private readonly onKey = (e: KeyboardEvent) => {
    const t = e.target as HTMLElement | null;
    if ((e.key !== 'f' && e.key !== 'F') || e.ctrlKey || e.metaKey || e.altKey || (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT'))) return;
    if (!this.current) return;
    e.preventDefault();
    this.faster();
  };

  constructor(
    private readonly animator: Playback,
    private readonly sound?: SoundPlayer,
  ) {
    this.button = h('button', { type: 'button', className: 'fast-forward', 'aria-label': 'Fast forward', 'aria-keyshortcuts': 'F', title: 'Play the shot faster: x2, x4, then its end (F)', hidden: true, onclick: () => this.faster() }, label(2));
    document.addEventListener('keydown', this.onKey);
  }

  get playing(): boolean {
    return this.current !== null;
  }

  get speed(): number {
    return this.current?.speed ?? 1;
  }

  /** The animation's time (s). */
  get time(): number {
    const c = this.current;
    return c ? Math.min(c.outcome.duration, c.from + ((performance.now() - c.at) / 1000) * c.speed) : 0;
  }

  /** Animates an outcome from its start at x1; resolves at its end (reached, skipped to or stopped). */
  play(outcome: Outcome): Promise<void> {
    this.finish();
    return new Promise((resolve) => {
      const sounds = document.hidden ? [] : soundSchedule(outcome);
      this.current = { outcome, sounds, resolve, speed: 1, from: 0, at: performance.now(), run: 0 };
      this.start();
    });
  }

  /** One step faster: x2, x4, then the end. */
  faster(): void {
    const c = this.current;
    if (!c) return;
    const next = nextPace(c.speed);
    c.from = this.time;
    if (next === 'end') {
      c.from = c.outcome.duration;
      c.speed = 1;
      this.sound?.stop();
    } else c.speed = next;
    this.start();
  }

  destroy(): void {
    document.removeEventListener('keydown', this.onKey);
    this.sound?.stop();
    this.finish();
  }

  private start(): void {
    const c = this.current!;
    c.at = performance.now();
    c.run = ++this.runs;
    this.button.hidden = false;
    const next = nextPace(c.speed);
    this.button.textContent = label(next);
    if (c.from < c.outcome.duration) this.sound?.play(c.sounds, c.from, c.speed);
    // The animator ends the previous run when it starts this one: only this run's end counts.
    const run = c.run;
    void this.animator.play(c.outcome, c.speed, c.from).then(() => {
      if (this.current === c && c.run === run) this.finish();
    });
  }

  private finish(): void {
    const c = this.current;
    this.current = null;
    this.button.hidden = true;
    c?.resolve();
  }
}
