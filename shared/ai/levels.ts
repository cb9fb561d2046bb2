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
  /** Pocket games: pots (object ball and pocket) tried per cue ball place. */
  readonly pots: number;
  /** Pocket games: speed and spin variants per pot (up to 14). */
  readonly variants: number;
  /** Pocket games: safety strokes tried. */
  readonly safeties: number;
  /** Pocket games: places tried for a ball in hand. */
  readonly spots: number;
  /** Pocket games: whether one-cushion banks are among the pots. */
  readonly banks: boolean;
}

export const LEVELS: Readonly<Record<Level, LevelSpec>> = {
  1: { heading: 0.014, speed: 0.12, tip: 0.12, samples: 1, breadth: 3, lookahead: false, pots: 2, variants: 1, safeties: 0, spots: 1, banks: false },
  2: { heading: 0.007, speed: 0.08, tip: 0.08, samples: 2, breadth: 6, lookahead: false, pots: 3, variants: 2, safeties: 6, spots: 2, banks: false },
  3: { heading: 0.0035, speed: 0.05, tip: 0.05, samples: 4, breadth: 10, lookahead: true, pots: 4, variants: 5, safeties: 12, spots: 3, banks: true },
  4: { heading: 0.0016, speed: 0.03, tip: 0.03, samples: 6, breadth: 16, lookahead: true, pots: 5, variants: 9, safeties: 20, spots: 4, banks: true },
  5: { heading: 0.0007, speed: 0.015, tip: 0.015, samples: 12, breadth: 24, lookahead: true, pots: 6, variants: 14, safeties: 30, spots: 5, banks: true },
};

export function isLevel(n: unknown): n is Level {
  return n === 1 || n === 2 || n === 3 || n === 4 || n === 5;
}
