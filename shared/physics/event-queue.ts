// A binary min-heap of predicted events. Keys are totally ordered (time, kind, balls, target), so
// the pop order never depends on insertion order: the simulation is the same on every engine.
// Predictions made stale by a later change of a ball stay in the heap and are skipped when popped
// (each carries the versions of the balls it was made for).

/** Event kinds, in the order they are handled when they fall at the same instant. */
export const Kind = { Motion: 0, Pocket: 1, Ball: 2, Cushion: 3 } as const;
export type Kind = (typeof Kind)[keyof typeof Kind];

export interface Prediction {
  t: number;
  kind: Kind;
  a: number;
  /** The other ball (Kind.Ball), the cushion or the pocket index; -1 for a motion change. */
  b: number;
  versionA: number;
  versionB: number;
}

function before(x: Prediction, y: Prediction): boolean {
  if (x.t !== y.t) return x.t < y.t;
  if (x.kind !== y.kind) return x.kind < y.kind;
  if (x.a !== y.a) return x.a < y.a;
  if (x.b !== y.b) return x.b < y.b;
  if (x.versionA !== y.versionA) return x.versionA < y.versionA;
  return x.versionB < y.versionB;
}

export class EventQueue {
  private readonly heap: Prediction[] = [];

  get size(): number {
    return this.heap.length;
  }

  push(p: Prediction): void {
    const h = this.heap;
    h.push(p);
    let i = h.length - 1;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (!before(h[i]!, h[parent]!)) break;
      [h[i], h[parent]] = [h[parent]!, h[i]!];
      i = parent;
    }
  }

  pop(): Prediction | undefined {
    const h = this.heap;
    const top = h[0];
    const last = h.pop();
    if (h.length > 0 && last) {
      h[0] = last;
      let i = 0;
      for (;;) {
        const l = 2 * i + 1;
        const r = l + 1;
        let m = i;
        if (l < h.length && before(h[l]!, h[m]!)) m = l;
        if (r < h.length && before(h[r]!, h[m]!)) m = r;
        if (m === i) break;
        [h[i], h[m]] = [h[m]!, h[i]!];
        i = m;
      }
    }
    return top;
  }
}
