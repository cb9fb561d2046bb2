// Reading a shot's outcome: the events of the simulation (issue 4) turned into the facts a referee
// judges by. Nothing here knows any game's rules.
import { RuleError } from './errors.ts';
import type { Ball, Outcome, OutcomeEvent } from './types.ts';

/** Events closer in time than this are simultaneous (seconds). */
export const SIMULTANEOUS = 1e-9;

export interface Pot {
  id: string;
  /** Pocket id, when the outcome names one. */
  pocket: string | undefined;
  /** Time of the pocket event; Infinity when only the final state says the ball went down. */
  t: number;
}

export interface ShotFacts {
  /** Events in time order (a stable sort of a copy). */
  events: OutcomeEvent[];
  /** The balls the struck ball met first (several when met at the same instant); empty if none. */
  firstHit: string[];
  /** Time of that first contact, or null. */
  firstHitT: number | null;
  /** Some ball met a cushion at or after the first contact (WPA 6.3). */
  cushionAfterContact: boolean;
  /** Balls that went down, in time order (the struck ball included). */
  pots: Pot[];
  /** Ids of the balls, other than the struck one, that met a cushion at any time of the shot. */
  ballsToCushion: Set<string>;
  /** Final positions of the balls still on the table, in the order of the balls before the shot. */
  remaining: Ball[];
}

/**
 * Check the outcome against the balls on the table before the shot and extract the facts. Balls
 * the outcome does not list stay where they were (unless a pocket event takes them).
 */
export function readOutcome(before: readonly Ball[], struck: string, outcome: Outcome): ShotFacts {
  if (!outcome || !Array.isArray(outcome.balls) || !Array.isArray(outcome.events)) {
    throw new RuleError('bad-outcome', 'the outcome must have arrays balls and events');
  }
  const known = new Set(before.map((b) => b.id));
  const final = new Map<string, { x: number; y: number; pocketed: boolean; pocket: string | undefined }>();
  for (const b of outcome.balls) {
    if (!known.has(b.id)) throw new RuleError('bad-outcome', `the outcome has ball "${b.id}", which is not on the table`);
    if (final.has(b.id)) throw new RuleError('bad-outcome', `the outcome lists ball "${b.id}" twice`);
    if (!b.pocketed && (!Number.isFinite(b.x) || !Number.isFinite(b.y))) {
      throw new RuleError('bad-outcome', `the outcome gives ball "${b.id}" a non-finite position`);
    }
    final.set(b.id, { x: b.x, y: b.y, pocketed: b.pocketed === true, pocket: b.pocket });
  }
  const events = outcome.events
    .map((e, i) => ({ e, i }))
    .sort((a, b) => a.e.t - b.e.t || a.i - b.i)
    .map(({ e }) => e);
  for (const e of events) {
    if (!Number.isFinite(e.t)) throw new RuleError('bad-outcome', `an event of kind "${e.kind}" has no finite time`);
    if (!Array.isArray(e.balls)) throw new RuleError('bad-outcome', `an event of kind "${e.kind}" has no balls array`);
    for (const id of e.balls) {
      if (!known.has(id)) throw new RuleError('bad-outcome', `an event names ball "${id}", which is not on the table`);
    }
  }

  let firstHitT: number | null = null;
  const firstHit: string[] = [];
  const ballsToCushion = new Set<string>();
  let cushionAfterContact = false;
  const pots: Pot[] = [];
  const potted = new Set<string>();
  for (const e of events) {
    if (e.kind === 'ball' && e.balls.includes(struck)) {
      const other = e.balls.find((id: string) => id !== struck);
      if (other !== undefined) {
        const t0: number = firstHitT ?? e.t;
        firstHitT = t0;
        if (e.t - t0 <= SIMULTANEOUS && !firstHit.includes(other)) firstHit.push(other);
      }
    } else if (e.kind === 'cushion') {
      for (const id of e.balls) if (id !== struck) ballsToCushion.add(id);
      if (firstHitT !== null && e.t >= firstHitT - SIMULTANEOUS) cushionAfterContact = true;
    } else if (e.kind === 'pocket') {
      for (const id of e.balls) {
        if (potted.has(id)) continue;
        potted.add(id);
        pots.push({ id, pocket: e.pocket ?? final.get(id)?.pocket, t: e.t });
      }
    }
  }
  for (const b of before) {
    const f = final.get(b.id);
    if (f?.pocketed && !potted.has(b.id)) {
      potted.add(b.id);
      pots.push({ id: b.id, pocket: f.pocket, t: Number.POSITIVE_INFINITY });
    }
  }
  const remaining: Ball[] = [];
  for (const b of before) {
    if (potted.has(b.id)) continue;
    const f = final.get(b.id);
    // + 0 turns -0 into 0: the Game stays the same through JSON.
    remaining.push(f ? { id: b.id, x: f.x + 0, y: f.y + 0 } : { id: b.id, x: b.x, y: b.y });
  }
  return { events, firstHit, firstHitT, cushionAfterContact, pots, ballsToCushion, remaining };
}
