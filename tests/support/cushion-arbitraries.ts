// fast-check arbitraries for cushion impacts, shared by the cushion property tests.
import fc from 'fast-check';
import type { CushionParams, CushionState } from '../../shared/physics/index.ts';
import { paperState, TABLE_PARAMS } from './cushion-cases.ts';

/** The issue's range: V0 0.05-5 m/s, incidence 0.5-89.5°, topspin k -1..2, sidespin k -2..2. */
export const issueRange = {
  V0: fc.double({ min: 0.05, max: 5, noNaN: true }),
  alpha: fc.double({ min: 0.5, max: 89.5, noNaN: true }),
  kT: fc.double({ min: -1, max: 2, noNaN: true }),
  kS: fc.double({ min: -2, max: 2, noNaN: true }),
};

/** An impact over the issue's range with the paper's or one table's constants. */
export const issueImpact: fc.Arbitrary<{ V0: number; params: CushionParams; state: CushionState }> = fc
  .tuple(issueRange.V0, issueRange.alpha, issueRange.kT, issueRange.kS, fc.integer({ min: 0, max: TABLE_PARAMS.length - 1 }))
  .map(([V0, alpha, kT, kS, which]) => {
    const params = TABLE_PARAMS[which]![1];
    return { V0, params, state: paperState(V0, alpha, kT, kS, params.R) };
  });
