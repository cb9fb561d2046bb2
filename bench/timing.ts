// Timing helpers for the benchmarks: warm up, then take the median of repeated samples.

/** Median of the per-call time of fn (ms), each sample timing enough calls to last ~minMs. */
export function medianMs(fn: () => void, samples = 9, minMs = 20): number {
  for (let i = 0; i < 3; i++) fn(); // warm the JIT
  let calls = 1;
  for (;;) {
    const t0 = performance.now();
    for (let i = 0; i < calls; i++) fn();
    if (performance.now() - t0 >= minMs) break;
    calls *= 2;
  }
  const times: number[] = [];
  for (let s = 0; s < samples; s++) {
    const t0 = performance.now();
    for (let i = 0; i < calls; i++) fn();
    times.push((performance.now() - t0) / calls);
  }
  return median(times);
}

export function median(xs: readonly number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m]! : 0.5 * (s[m - 1]! + s[m]!);
}

export function fmt(x: number, digits = 3): string {
  if (x === 0) return '0';
  if (Math.abs(x) >= 100) return x.toFixed(0);
  if (Math.abs(x) >= 0.01) return x.toPrecision(digits);
  return x.toExponential(1);
}
