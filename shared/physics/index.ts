// The one entry point of the physics module: everything server, client, tests and benchmarks use.
export { tableSpec, isTableName, TABLE_NAMES, cushionParamsOf } from './tables.ts';
export type { TableName, TableSpec } from './tables.ts';
export { cushionRebound, cushionImpact, cushionTrace } from './cushion.ts';
export type { CushionStateOut, CushionImpact } from './cushion.ts';
export type { CushionTracePoint } from './cushion-solver.ts';
export { CUSHION_TOLERANCES } from './cushion-types.ts';
export type { CushionState, CushionParams, CushionOptions, CushionOutcome, CushionToleranceName } from './cushion-types.ts';
export { simulate } from './simulate.ts';
export { sampleOutcome, energyAt } from './trajectory.ts';
export type { BallAtTime } from './trajectory.ts';
export { SimulationInputError } from './validate-input.ts';
export { MiscueError } from './strike.ts';
export type { Scene, SceneBall, Shot, SimOptions, SimEvent, EventKind, FinalBall, Outcome, PathSegment } from './sim-types.ts';
export type { Motion } from './ball-state.ts';
export type { Pocket, Cushion } from './table-geometry.ts';
