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

/**
 * Constants of real tables around the ones in shared/physics/tables.ts: ball radius 26-32 mm
 * and mass 0.14-0.22 kg, cushion nose 1.2-1.65 R, e_e 0.7-1, ball-table friction 0.1-0.35,
 * ball-cushion friction 0.08-0.33.
 */
export const physicalParams: fc.Arbitrary<CushionParams> = fc
  .tuple(
    fc.double({ min: 0.026, max: 0.032, noNaN: true }),
    fc.double({ min: 0.14, max: 0.22, noNaN: true }),
    fc.double({ min: 1.2, max: 1.65, noNaN: true }),
    fc.double({ min: 0.7, max: 1, noNaN: true }),
    fc.double({ min: 0.1, max: 0.35, noNaN: true }),
    fc.double({ min: 0.08, max: 0.33, noNaN: true }),
  )
  .map(([R, M, hR, ee, muS, muW]) => ({ M, R, h: hR * R, ee, muS, muW }));
