// The one-line JSON summary a bot run prints, shared with the benchmark that reads it.
import type { BotStats } from './bot.ts';

export interface Summary {
  readonly rooms: number;
  readonly sockets: number;
  readonly gamesFinished: number;
  readonly shots: number;
  readonly errors: number;
  /** Shot round trips; null when no shot came back. */
  readonly rttMs: { readonly p50: number | null; readonly p99: number | null };
  /** The yardstick in the same run: round trips of a request the server refuses at once (no simulation, no write). */
  readonly yardstickMs: { readonly p50: number | null; readonly p99: number | null };
  /** Wall time of the run, from start to the end of play. */
  readonly seconds: number;
  readonly errorCodes: Readonly<Record<string, number>>;
  /** Sockets the server closed during play. */
  readonly disconnects: number;
  /** Rooms that could not be set up (connect, hello, create or join failed). */
  readonly setupFailures: number;
}

/** The nearest-rank percentile of `values` (p in 0..100), or null for none. */
export function percentile(values: readonly number[], p: number): number | null {
  if (values.length === 0) return null;
  const sorted = [...values].sort((a, b) => a - b);
  const rank = Math.max(1, Math.ceil((p / 100) * sorted.length));
  return sorted[Math.min(rank, sorted.length) - 1]!;
}

const round1 = (x: number | null): number | null => (x === null ? null : Math.round(x * 10) / 10);

export function summarize(
  stats: BotStats,
  run: { rooms: number; sockets: number; seconds: number; setupFailures: number; yardstickMs: readonly number[] },
): Summary {
  return {
    rooms: run.rooms,
    sockets: run.sockets,
    gamesFinished: stats.gamesFinished,
    shots: stats.shots,
    errors: stats.errors,
    rttMs: { p50: round1(percentile(stats.rttMs, 50)), p99: round1(percentile(stats.rttMs, 99)) },
    yardstickMs: { p50: round1(percentile(run.yardstickMs, 50)), p99: round1(percentile(run.yardstickMs, 99)) },
    seconds: Math.round(run.seconds * 100) / 100,
    errorCodes: stats.errorCodes,
    disconnects: stats.disconnects,
    setupFailures: run.setupFailures,
  };
}
