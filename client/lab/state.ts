// The lab's state: the cushion constants and the incoming ball, read from and written to the
// page's URL (so that a view can be shared), with the bounds each input accepts.
import type { CushionParams } from '../../shared/physics/index.ts';
import { FIG12_BALL, type IncomingBall } from './figures.ts';
import { PAPER } from '../../shared/scenes/index.ts';

export interface LabState {
  readonly params: CushionParams;
  readonly ball: IncomingBall;
}

export type Field = keyof CushionParams | keyof IncomingBall;

/** Each input: its label (the accessible name), unit, bounds and step. */
export const FIELDS: readonly { key: Field; label: string; min: number; max: number; step: number }[] = [
  { key: 'M', label: 'mass (kg)', min: 0.05, max: 0.5, step: 0.001 },
  { key: 'R', label: 'radius (m)', min: 0.02, max: 0.04, step: 0.0001 },
  { key: 'h', label: 'cushion height (m)', min: 0.02, max: 0.08, step: 0.0001 },
  { key: 'ee', label: 'restitution (e_e)', min: 0, max: 1, step: 0.01 },
  { key: 'muS', label: 'table friction (μs)', min: 0, max: 1, step: 0.001 },
  { key: 'muW', label: 'cushion friction (μw)', min: 0, max: 1, step: 0.001 },
  { key: 'V0', label: 'speed V0 (m/s)', min: 0.05, max: 5, step: 0.01 },
  { key: 'alpha', label: 'incidence α (°)', min: 0.5, max: 89.5, step: 0.5 },
  { key: 'kT', label: 'topspin k_T (ω R / V0)', min: -1, max: 2, step: 0.1 },
  { key: 'kS', label: 'sidespin k_S (ω R / V0)', min: -2, max: 2, step: 0.1 },
];

export const DEFAULT_STATE: LabState = { params: PAPER, ball: FIG12_BALL };

const get = (s: LabState, k: Field): number => (k in s.params ? s.params[k as keyof CushionParams] : s.ball[k as keyof IncomingBall]);

/** The state with one field set, or an error naming why the value is refused. */
export function withField(s: LabState, key: Field, value: number): LabState | string {
  const f = FIELDS.find((x) => x.key === key)!;
  if (!Number.isFinite(value)) return `${f.label}: not a number`;
  if (value < f.min || value > f.max) return `${f.label}: must lie in [${f.min}, ${f.max}]`;
  const next: LabState = key in s.params ? { ...s, params: { ...s.params, [key]: value } } : { ...s, ball: { ...s.ball, [key]: value } };
  const { R, h } = next.params;
  if (!(h > R && h < 2 * R)) return `cushion height must lie between R and 2R (${R} and ${2 * R} m)`;
  return next;
}

export function value(s: LabState, key: Field): number {
  return get(s, key);
}

/** The state in a query string (only what differs from the default). */
export function toQuery(s: LabState): string {
  const q = new URLSearchParams();
  for (const f of FIELDS) if (get(s, f.key) !== get(DEFAULT_STATE, f.key)) q.set(f.key, String(get(s, f.key)));
  const text = q.toString();
  return text ? `?${text}` : '';
}

/** The state a query string describes; a refused or unknown value keeps the default. */
export function fromQuery(search: string): LabState {
  const q = new URLSearchParams(search);
  let s = DEFAULT_STATE;
  for (const f of FIELDS) {
    const raw = q.get(f.key);
    if (raw === null) continue;
    const next = withField(s, f.key, Number(raw));
    if (typeof next !== 'string') s = next;
  }
  return s;
}
