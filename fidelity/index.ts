// The simulation against tracked real shots: reading the data, fitting strikes and the table's
// constants (npm run fidelity, docs/fidelity.md).
export { DATA_SCALE, readShots, rollingDeceleration, toShot } from './data.ts';
export type { Track, TrackedShot } from './data.ts';
export {
  ballMap, CONSTANTS, constantsOf, errorByPhase, firstContactTime, fitStrike, NOT_EXPRESSED, openingError, percentile, residuals, rmsError, sceneOf,
  seedStrike, shotOf, simulateShot, t0Range, TABLE, tableWith,
} from './fit.ts';
export type { Strike } from './fit.ts';
export { fitShot, fitTable } from './search.ts';
export { nelderMead } from './nelder-mead.ts';
export { cushionRebounds, openingAlongAcross, openingRun, slowRuns, trackedAs } from './analysis.ts';
export type { Rebound, SlowRuns } from './analysis.ts';
