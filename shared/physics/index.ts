// The one entry point of the physics module: what the server, the client and outside callers use.
// Diagnostics (the cushion impact's step counts and trace) have an entry of their own: diagnostics.ts.
export { tableSpec, isTableName, TABLE_NAMES, cushionParamsOf } from './tables.ts';
export type { TableName, TableSpec } from './tables.ts';
export { cushionRebound, CUSHION_TOLERANCES } from './cushion/index.ts';
export type { CushionState, CushionParams, CushionOptions, CushionOutcome, CushionToleranceName } from './cushion/index.ts';
export { simulate } from './simulate.ts';
export { sampleOutcome, energyAt } from './trajectory.ts';
export type { BallAtTime } from './trajectory.ts';
export { SimulationInputError } from './validate-input.ts';
export { MiscueError, MISCUE_LIMIT } from './strike.ts';
export { detAtan2, sinCos, wrapAngle } from './det-math.ts';
export type { Scene, SceneBall, Shot, SimOptions, SimEvent, EventKind, FinalBall, Outcome, PathSegment } from './sim-types.ts';
export type { Motion } from './ball-state.ts';
export type { Pocket, Cushion } from './table-geometry.ts';
