// Input checks for cushionRebound: every bad field throws a RangeError that names it.
import type { CushionOptions, CushionParams, CushionState } from './cushion-types.ts';
import { CUSHION_TOLERANCES } from './cushion-types.ts';

const STATE_FIELDS = ['vx', 'vy', 'wx', 'wy', 'wz'] as const;
const PARAM_FIELDS = ['M', 'R', 'h', 'ee', 'muS', 'muW'] as const;

/** Smallest and largest numeric tolerance accepted. */
export const MIN_TOLERANCE = 1e-12;
export const MAX_TOLERANCE = 1e-2;

function fail(field: string, rule: string, value: unknown): never {
  throw new RangeError(`cushionRebound: ${field} ${rule}, got ${String(value)}`);
}

function finite(field: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(field, 'must be a finite number', value);
  return value;
}

export function validateState(state: CushionState): void {
  if (state === null || typeof state !== 'object') fail('state', 'must be an object', state);
  for (const f of STATE_FIELDS) finite(`state.${f}`, state[f]);
}

export function validateParams(params: CushionParams): void {
  if (params === null || typeof params !== 'object') fail('params', 'must be an object', params);
  for (const f of PARAM_FIELDS) finite(`params.${f}`, params[f]);
  if (!(params.M > 0)) fail('params.M', 'must be positive', params.M);
  if (!(params.R > 0)) fail('params.R', 'must be positive', params.R);
  if (!(params.h > params.R && params.h < 2 * params.R)) {
    fail('params.h', `must lie in (R, 2R) = (${params.R}, ${2 * params.R})`, params.h);
  }
  if (!(params.ee >= 0 && params.ee <= 1)) fail('params.ee', 'must lie in [0, 1]', params.ee);
  if (!(params.muS >= 0)) fail('params.muS', 'must be non-negative', params.muS);
  if (!(params.muW >= 0)) fail('params.muW', 'must be non-negative', params.muW);
}

/** The numeric tolerance chosen by the options (default: 'accurate'). */
export function resolveTolerance(options: CushionOptions | undefined): number {
  if (options === undefined) return CUSHION_TOLERANCES.accurate;
  if (options === null || typeof options !== 'object') fail('options', 'must be an object', options);
  const t = options.tolerance;
  if (t === undefined) return CUSHION_TOLERANCES.accurate;
  if (typeof t === 'string') {
    if (Object.prototype.hasOwnProperty.call(CUSHION_TOLERANCES, t)) {
      return CUSHION_TOLERANCES[t as keyof typeof CUSHION_TOLERANCES];
    }
    fail('options.tolerance', `must be one of ${Object.keys(CUSHION_TOLERANCES).join(', ')} or a number`, t);
  }
  const v = finite('options.tolerance', t);
  if (!(v >= MIN_TOLERANCE && v <= MAX_TOLERANCE)) {
    fail('options.tolerance', `must lie in [${MIN_TOLERANCE}, ${MAX_TOLERANCE}]`, v);
  }
  return v;
}
