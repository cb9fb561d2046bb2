// Notices when the server's own event loop stalled (a long computation, a pause of the process),
// so that rate limits do not punish frames that queued up meanwhile: a client sending steadily
// within its limit has its frames of the whole stall read at once when the loop runs again.
// A heartbeat every BEAT_MS notes when it last ran; a beat later than STALL_MS was a stall.

const BEAT_MS = 100;
/** A delay shorter than this is ordinary jitter, not a stall. */
const STALL_MS = 250;
/** How long after a stall its frames may still be arriving (the backlog is read in a few turns). */
const GRACE_MS = 1000;

export class StallWatch {
  private beat: number;
  private last = { length: 0, end: -Infinity };
  private readonly timer: NodeJS.Timeout;

  constructor(private readonly now: () => number = Date.now) {
    this.beat = now();
    this.timer = setInterval(() => {
      const t = this.now();
      const late = t - this.beat - BEAT_MS;
      if (late > STALL_MS) this.last = { length: late, end: t };
      this.beat = t;
    }, BEAT_MS);
    this.timer.unref();
  }

  /**
   * How long the loop stalled just before `now` (ms): the stall it is coming out of (the heartbeat
   * has not run since), or the last one if it ended within GRACE_MS; 0 when there was none.
   */
  recent(now: number): number {
    const current = now - this.beat - BEAT_MS;
    if (current > STALL_MS) return current;
    return now - this.last.end <= GRACE_MS ? this.last.length : 0;
  }

  stop(): void {
    clearInterval(this.timer);
  }
}
