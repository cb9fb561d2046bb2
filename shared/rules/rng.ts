// The seeded generator. Its whole state is one uint32 kept in the Game (as boardgame.io keeps its
// PRNG state in the game state), so a Game replays identically on server and client.
//
// Generator: Marsaglia's xorshift32 with the shift triple (13, 17, 5) ("Xorshift RNGs", Journal of
// Statistical Software 8(14), 2003), whose state must be non-zero. The output is the state
// multiplied by an odd constant (Math.imul is exact 32-bit arithmetic on every engine), which hides
// the low-bit weakness of plain xorshift. Only integer operations: deterministic everywhere.

/** A seed (number or string) turned into a non-zero generator state. */
export function seedState(seed: number | string | undefined): number {
  let h: number;
  if (seed === undefined) {
    h = 1;
  } else if (typeof seed === 'number') {
    if (!Number.isFinite(seed)) throw new RangeError(`seed must be a finite number, got ${seed}`);
    // Keep 32 bits of the integer part (two's complement wrap), as a uint32.
    h = Math.trunc(seed) >>> 0;
  } else {
    // FNV-1a over UTF-16 code units (Fowler, Noll, Vo), 32-bit.
    h = 0x811c9dc5;
    for (let i = 0; i < seed.length; i++) {
      h ^= seed.charCodeAt(i);
      h = Math.imul(h, 0x01000193) >>> 0;
    }
  }
  // Scramble so that nearby seeds give unrelated states: the 32-bit finaliser of MurmurHash3
  // (Appleby), written out here.
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  h >>>= 0;
  return h === 0 ? 0x9e3779b9 : h;
}

/** One step: the next state and a uint32 output. */
export function nextUint32(state: number): { value: number; state: number } {
  let x = state >>> 0 || 0x9e3779b9;
  x ^= x << 13;
  x >>>= 0;
  x ^= x >>> 17;
  x ^= x << 5;
  x >>>= 0;
  return { value: Math.imul(x, 0x2545f491) >>> 0, state: x };
}

/** A uniform integer in [0, n), by rejection (no modulo bias). */
export function nextInt(state: number, n: number): { value: number; state: number } {
  if (!Number.isInteger(n) || n <= 0 || n > 0x100000000) throw new RangeError(`bad range ${n}`);
  const limit = Math.floor(0x100000000 / n) * n;
  let s = state;
  for (;;) {
    const r = nextUint32(s);
    s = r.state;
    if (r.value < limit) return { value: r.value % n, state: s };
  }
}

/** A shuffled copy (Fisher-Yates, Knuth's Algorithm P) and the generator state after it. */
export function shuffle<T>(items: readonly T[], state: number): { items: T[]; state: number } {
  const out = items.slice();
  let s = state;
  for (let i = out.length - 1; i > 0; i--) {
    const r = nextInt(s, i + 1);
    s = r.state;
    const j = r.value;
    const a = out[i] as T;
    out[i] = out[j] as T;
    out[j] = a;
  }
  return { items: out, state: s };
}
