// What makes the levels differ: the execution noise the computer plays with (and expects while it
// searches), and how widely it searches. Sigmas are of a Gaussian on each stroke parameter.
import type { Level } from './types.ts';

export interface LevelSpec {
  /** Heading error, radians (1 mrad is about 1 mm over a metre). */
  readonly heading: number;
  /** Speed error, as a fraction of the speed. */
  readonly speed: number;
  /** Tip offset error, as a fraction of R. */
  readonly tip: number;
  /** Noisy samples per candidate while searching. */
  readonly samples: number;
  /** Candidates kept after the cheap geometric ranking, to be simulated. */
  readonly breadth: number;
  /** Whether the search looks one shot ahead (position play). */
  readonly lookahead: boolean;
}

export const LEVELS: Readonly<Record<Level, LevelSpec>> = {
  1: { heading: 0.02, speed: 0.15, tip: 0.15, samples: 1, breadth: 4, lookahead: false },
  2: { heading: 0.01, speed: 0.1, tip: 0.1, samples: 2, breadth: 8, lookahead: false },
  3: { heading: 0.005, speed: 0.06, tip: 0.06, samples: 4, breadth: 16, lookahead: true },
  4: { heading: 0.0025, speed: 0.04, tip: 0.04, samples: 6, breadth: 24, lookahead: true },
  5: { heading: 0.001, speed: 0.02, tip: 0.02, samples: 8, breadth: 32, lookahead: true },
};

export function isLevel(n: unknown): n is Level {
  return n === 1 || n === 2 || n === 3 || n === 4 || n === 5;
}
