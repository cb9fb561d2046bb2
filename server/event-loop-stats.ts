// The event loop's delay as perf_hooks measures it, for load tests (BAIZE_EVENT_LOOP_STATS=1 serves
// it at GET /diagnostics/event-loop): percentiles in ms since the start or the last reset. A sample
// is the time between two timer turns of 1 ms, so it includes that 1 ms.
import { monitorEventLoopDelay } from 'node:perf_hooks';

export interface EventLoopStats {
  /** p50, p99 and max in ms, and how many samples; `reset` starts a new measurement after reading. */
  read(reset: boolean): { p50: number; p99: number; max: number; mean: number; samples: number };
  stop(): void;
}

export function eventLoopStats(resolutionMs = 1): EventLoopStats {
  const h = monitorEventLoopDelay({ resolution: resolutionMs });
  h.enable();
  const ms = (ns: number) => Math.round(ns / 1e4) / 100;
  return {
    read(reset) {
      const out = { p50: ms(h.percentile(50)), p99: ms(h.percentile(99)), max: ms(h.max), mean: ms(h.mean), samples: h.count };
      if (reset) h.reset();
      return out;
    },
    stop: () => h.disable(),
  };
}
