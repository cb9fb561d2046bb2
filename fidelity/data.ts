// The tracked three-cushion shots (tailuge/billiards, dist/fit/trajectories.json): read, brought to
// the match table's scale, each ball's samples in time order, and the cue ball found.
import { readFileSync } from 'node:fs';

/** The file's positions were scaled by 0.03275 / 0.03075 to a larger table (its README). */
export const DATA_SCALE = 1.06507;

export interface Track {
  readonly t: readonly number[];
  readonly x: readonly number[];
  readonly y: readonly number[];
}

export interface TrackedShot {
  readonly id: number;
  /** The data's ball ids "1", "2", "3" and their tracks on the match table (m, s). */
  readonly balls: Readonly<Record<string, Track>>;
  /** The cue ball: the one whose second sample comes first. */
  readonly cue: string;
}

interface RawShot {
  id: number;
  balls: Record<string, { t: number[]; x: number[]; y: number[] }>;
}

/** The shots in a file of the data's format; throws with a clear message when it is missing or malformed. */
export function readShots(path: string): TrackedShot[] {
  let raw: RawShot[];
  try {
    raw = JSON.parse(readFileSync(path, 'utf8')) as RawShot[];
  } catch (err) {
    throw new Error(`fidelity: cannot read the tracked shots at ${path}: ${(err as Error).message}`);
  }
  if (!Array.isArray(raw)) throw new Error(`fidelity: ${path} is not a list of shots`);
  return raw.map(toShot);
}

export function toShot(r: RawShot): TrackedShot {
  const balls: Record<string, Track> = {};
  for (const [id, b] of Object.entries(r.balls)) {
    const t: number[] = [];
    const x: number[] = [];
    const y: number[] = [];
    b.t.forEach((ti, i) => {
      // (A repeated time keeps its first sample.)
      if (t.length > 0 && ti <= t[t.length - 1]!) return;
      t.push(ti);
      x.push(b.x[i]! / DATA_SCALE);
      y.push(b.y[i]! / DATA_SCALE);
    });
    balls[id] = { t, x, y };
  }
  const ids = Object.keys(balls).sort();
  if (ids.length !== 3) throw new Error(`fidelity: shot ${r.id} has ${ids.length} balls, not 3`);
  const second = (id: string): number => balls[id]!.t[1] ?? Infinity;
  const cue = ids.reduce((a, b) => (second(b) < second(a) ? b : a));
  return { id: r.id, balls, cue };
}

/**
 * The cloth's rolling deceleration read from the data (m/s²): over every window of 0.5 s in which
 * a ball runs straight (its direction turns less than 2°) at under 1.5 m/s, 1 s or more after the
 * strike (rolling by then), the slope of its speed against time; the median over windows.
 */
export function rollingDeceleration(shots: readonly TrackedShot[]): number {
  const slopes: number[] = [];
  const W = 25;
  for (const s of shots) {
    for (const b of Object.values(s.balls)) {
      const v: { t: number; v: number; dir: number }[] = [];
      for (let i = 1; i + 1 < b.t.length; i++) {
        const dt = b.t[i + 1]! - b.t[i - 1]!;
        if (Math.abs(dt - 0.04) > 1e-9 || b.t[i]! < 1) continue;
        const dx = b.x[i + 1]! - b.x[i - 1]!;
        const dy = b.y[i + 1]! - b.y[i - 1]!;
        v.push({ t: b.t[i]!, v: Math.hypot(dx, dy) / dt, dir: Math.atan2(dy, dx) });
      }
      for (let i = 0; i + W <= v.length; i += W) {
        const w = v.slice(i, i + W);
        if (w[W - 1]!.t - w[0]!.t > 0.5 + 1e-9) continue;
        const turn = Math.abs(Math.atan2(Math.sin(w[W - 1]!.dir - w[0]!.dir), Math.cos(w[W - 1]!.dir - w[0]!.dir)));
        if (turn > (2 * Math.PI) / 180 || w.some((p) => p.v > 1.5 || p.v < 0.05)) continue;
        const mt = w.reduce((a, p) => a + p.t, 0) / W;
        const mv = w.reduce((a, p) => a + p.v, 0) / W;
        const slope = w.reduce((a, p) => a + (p.t - mt) * (p.v - mv), 0) / w.reduce((a, p) => a + (p.t - mt) ** 2, 0);
        slopes.push(-slope);
      }
    }
  }
  slopes.sort((a, b) => a - b);
  return slopes[slopes.length >> 1] ?? NaN;
}
