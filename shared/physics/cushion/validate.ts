// Input checks for cushionRebound: every bad field throws a RangeError that names it.
import type { CushionOptions, CushionParams, CushionState } from './types.ts';
import { CUSHION_TOLERANCES } from './types.ts';

/** Smallest and largest numeric tolerance accepted. */
export const MIN_TOLERANCE = 1e-12;
export const MAX_TOLERANCE = 1e-2;

function fail(field: string, rule: string, value: unknown): never {
  throw new RangeError(`cushionRebound: ${field} ${rule}, got ${String(value)}`);
}

// Number.isFinite is false for NaN, ±Infinity and non-numbers. The messages are built only on
// failure (this runs on every impact).
function checkFinite(name: string, field: string, value: unknown): void {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(`${name}.${field}`, 'must be a finite number', value);
}

const STATE_FIELDS = ['vx', 'vy', 'wx', 'wy', 'wz'] as const;
const PARAM_FIELDS = ['M', 'R', 'h', 'ee', 'muS', 'muW'] as const;

export function validateState(state: CushionState): void {
  if (state === null || typeof state !== 'object') fail('state', 'must be an object', state);
  const { vx, vy, wx, wy, wz } = state;
  if (Number.isFinite(vx) && Number.isFinite(vy) && Number.isFinite(wx) && Number.isFinite(wy) && Number.isFinite(wz)) return;
  for (const field of STATE_FIELDS) checkFinite('state', field, state[field]);
}

export function validateParams(params: CushionParams): void {
  if (params === null || typeof params !== 'object') fail('params', 'must be an object', params);
  const { M, R, h, ee, muS, muW } = params;
  if (!(Number.isFinite(M) && Number.isFinite(R) && Number.isFinite(h) && Number.isFinite(ee) && Number.isFinite(muS) && Number.isFinite(muW))) {
    for (const field of PARAM_FIELDS) checkFinite('params', field, params[field]);
  }
  if (!(M > 0)) fail('params.M', 'must be positive', M);
  if (!(R > 0)) fail('params.R', 'must be positive', R);
  if (!(h > R && h < 2 * R)) fail('params.h', `must lie in (R, 2R) = (${R}, ${2 * R})`, h);
  if (!(ee >= 0 && ee <= 1)) fail('params.ee', 'must lie in [0, 1]', ee);
  if (!(muS >= 0)) fail('params.muS', 'must be non-negative', muS);
  if (!(muW >= 0)) fail('params.muW', 'must be non-negative', muW);
}

/** The numeric tolerance chosen by the options (default: 'accurate'). */
export function resolveTolerance(options: CushionOptions | undefined): number {
  if (options === undefined) return CUSHION_TOLERANCES.accurate;
  if (options === null || typeof options !== 'object') fail('options', 'must be an object', options);
  const t = options.tolerance;
  if (t === undefined) return CUSHION_TOLERANCES.accurate;
  // The names first, by comparison (the benchmark passes one on every call).
  if (t === 'accurate' || t === 'balanced' || t === 'fast') return CUSHION_TOLERANCES[t];
  if (typeof t === 'string') {
    if (Object.prototype.hasOwnProperty.call(CUSHION_TOLERANCES, t)) {
      return CUSHION_TOLERANCES[t as keyof typeof CUSHION_TOLERANCES];
    }
    fail('options.tolerance', `must be one of ${Object.keys(CUSHION_TOLERANCES).join(', ')} or a number`, t);
  }
  if (typeof t !== 'number' || !Number.isFinite(t)) fail('options.tolerance', 'must be a finite number', t);
  const v = t;
  if (!(v >= MIN_TOLERANCE && v <= MAX_TOLERANCE)) {
    fail('options.tolerance', `must lie in [${MIN_TOLERANCE}, ${MAX_TOLERANCE}]`, v);
  }
  return v;
}
