// The physics' diagnostic entry: the cushion impact with its outcome and step counts, and its
// trace along the impulse (Fig. 12, the lab). The same solver as cushionRebound, which is what the
// product uses (index.ts); these only report more.
export { cushionImpact, cushionTrace } from './cushion/index.ts';
export { MAX_STEPS } from './cushion/control.ts';
export type { CushionStateOut, CushionImpact, CushionTracePoint } from './cushion/index.ts';
export { simulateOn } from './simulate.ts';
