// What /proc says about one process (Linux): CPU time used so far and resident memory, sampled over
// time so that a window of the samples gives its CPU share and peak RSS.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';

/** Clock ticks a second, the unit of utime and stime in /proc/<pid>/stat. */
function clockTicks(): number {
  try {
    const n = Number(execFileSync('getconf', ['CLK_TCK'], { encoding: 'utf8' }).trim());
    return Number.isInteger(n) && n > 0 ? n : 100;
  } catch {
    return 100;
  }
}
const TICKS = clockTicks();

/** CPU seconds (user + system) the process has used. */
export function cpuSeconds(pid: number): number {
  const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
  // The command name, field 2, is in parentheses and may hold spaces: count fields after its end.
  const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
  return (Number(fields[11]) + Number(fields[12])) / TICKS; // fields 14 and 15 of stat
}

/** Resident set size in MB (VmRSS). */
export function rssMb(pid: number): number {
  const m = /^VmRSS:\s+(\d+)\s+kB/m.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
  return m ? Number(m[1]) / 1024 : NaN;
}

export interface Sample {
  /** performance.now() of this process, ms. */
  readonly at: number;
  readonly cpu: number;
  readonly rss: number;
}

/** Samples the process every `everyMs` until stopped. */
export class ProcSampler {
  readonly samples: Sample[] = [];
  private readonly timer: NodeJS.Timeout;

  constructor(
    private readonly pid: number,
    everyMs = 500,
  ) {
    this.sample();
    this.timer = setInterval(() => this.sample(), everyMs);
  }

  sample(): Sample | undefined {
    try {
      const s = { at: performance.now(), cpu: cpuSeconds(this.pid), rss: rssMb(this.pid) };
      this.samples.push(s);
      return s;
    } catch {
      return undefined; // the process is gone
    }
  }

  stop(): void {
    clearInterval(this.timer);
  }

  /** CPU as % of one core, and peak RSS (MB), between the samples nearest to `from` and `to`. */
  window(from: number, to: number): { cpuPercent: number; rssPeakMb: number } {
    const inside = this.samples.filter((s) => s.at >= from && s.at <= to);
    const before = [...this.samples].reverse().find((s) => s.at <= from) ?? this.samples[0];
    const first = before ?? inside[0];
    const last = inside[inside.length - 1];
    if (!first || !last || last.at <= first.at) return { cpuPercent: NaN, rssPeakMb: NaN };
    return {
      cpuPercent: (100 * (last.cpu - first.cpu)) / ((last.at - first.at) / 1000),
      rssPeakMb: Math.max(first.rss, ...inside.map((s) => s.rss)),
    };
  }
}
