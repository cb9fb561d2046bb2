// How widely the computer searches at three-cushion, per level: the coarse grid of strokes, how
// many scoring regions it refines, how many strokes it judges under the level's noise, and how far
// it looks at the position it leaves. Kept apart from ../levels.ts (shared with the pocket games).
import type { Level } from '../types.ts';

export interface CaromBreadth {
  /** Step of the all-round headings (bank-first and round-the-table paths), radians. */
  readonly headingStep: number;
  /** Contact points per side of each object ball (thin to thick hits). */
  readonly cuts: number;
  /** Speeds of the coarse grid, m/s. */
  readonly speeds: readonly number[];
  /** Side (horizontal tip offset, fraction of R) of the coarse grid. */
  readonly sides: readonly number[];
  /** Top or draw (vertical tip offset, fraction of R) of the coarse grid. */
  readonly tops: readonly number[];
  /** Scoring regions refined to their centre. */
  readonly regions: number;
  /** Refined strokes judged under the level's noise. */
  readonly judged: number;
  /** Noisy samples per judged stroke. */
  readonly samples: number;
  /** Strokes around which the position left is probed (0: a geometric guess instead). */
  readonly probes: number;
  /** Strokes of the probe grid that rates the position left (scoring strokes found there). */
  readonly probeGrid: number;
}

const D = Math.PI / 180;

export const CAROM_BREADTH: Readonly<Record<Level, CaromBreadth>> = {
  1: { headingStep: 6 * D, cuts: 3, speeds: [3.5], sides: [-0.3, 0.3], tops: [0.2], regions: 2, judged: 2, samples: 2, probes: 0, probeGrid: 0 },
  2: { headingStep: 4 * D, cuts: 4, speeds: [3, 4.5], sides: [-0.3, 0.3], tops: [0.2], regions: 4, judged: 3, samples: 4, probes: 0, probeGrid: 0 },
  3: { headingStep: 4 * D, cuts: 5, speeds: [2.8, 4.2], sides: [-0.35, 0.35], tops: [0.2], regions: 5, judged: 4, samples: 6, probes: 2, probeGrid: 40 },
  4: { headingStep: 3 * D, cuts: 6, speeds: [2.5, 3.5, 4.8], sides: [-0.4, 0, 0.4], tops: [0.2], regions: 8, judged: 6, samples: 8, probes: 3, probeGrid: 60 },
  5: { headingStep: 2.5 * D, cuts: 8, speeds: [2.3, 3.2, 4.3, 5.4], sides: [-0.4, 0, 0.4], tops: [0.2], regions: 10, judged: 8, samples: 12, probes: 4, probeGrid: 80 },
};
