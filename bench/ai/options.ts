// Options of bench:ai: --games N (games per pairing), --racks N (run-out racks), --frames N
// (snooker break frames), --innings N (three-cushion innings), --only pool,snooker,carom,cost (sections), --levels 1,2,3,4,5, --budget S
// (seconds per table before it stops early and says how many it played). Small defaults.
export interface BenchOptions {
  readonly games: number;
  readonly racks: number;
  readonly frames: number;
  readonly only: readonly string[];
  readonly levels: readonly number[];
  readonly budget: number;
  readonly kinds: readonly string[];
  /** Three-cushion innings per level (points per inning). */
  readonly innings: number;
}

export function readOptions(argv: readonly string[]): BenchOptions {
  const get = (name: string): string | undefined => {
    const i = argv.indexOf(`--${name}`);
    return i >= 0 ? argv[i + 1] : undefined;
  };
  const num = (name: string, fallback: number): number => {
    const v = Number(get(name) ?? fallback);
    if (!Number.isFinite(v) || v < 0) throw new Error(`--${name} must be a number`);
    return v;
  };
  const list = (name: string, fallback: string): string[] => (get(name) ?? fallback).split(',').filter((s) => s.length > 0);
  return {
    games: num('games', 4),
    racks: num('racks', 10),
    frames: num('frames', 4),
    only: list('only', 'pool,snooker,carom,cost'),
    levels: list('levels', '1,2,3,4,5').map(Number),
    budget: num('budget', 300),
    kinds: list('kinds', 'nineball,eightball'),
    innings: num('innings', 20),
  };
}

/** A clock for a table's time budget. */
export function deadline(seconds: number): () => boolean {
  const end = performance.now() + seconds * 1000;
  return () => performance.now() > end;
}
