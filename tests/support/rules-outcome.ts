// Synthetic outcomes for the referee tests: a small builder that writes the events a simulation
// would report (ball contacts, cushions, pockets) in time order, and the final positions.
import { expect } from 'vitest';
import { cueBallId, RuleError } from '../../shared/rules/index.ts';
import type { Ball, Game, Outcome, OutcomeEvent, PocketId, Shot } from '../../shared/rules/index.ts';

export class OutcomeBuilder {
  private t = 0;
  private readonly events: OutcomeEvent[] = [];
  private readonly finals = new Map<string, { x: number; y: number }>();
  private readonly pockets = new Map<string, string | undefined>();
  private readonly start: Ball[];

  constructor(start: Game | readonly Ball[]) {
    this.start = (Array.isArray(start) ? start : (start as Game).balls).map((b) => ({ ...b }));
  }

  private tick(): number {
    this.t += 0.1;
    return Math.round(this.t * 1e6) / 1e6;
  }

  /** a meets b (a fresh instant). */
  hit(a: string, b: string): this {
    this.events.push({ t: this.tick(), kind: 'ball', balls: [a, b] });
    return this;
  }

  /** a meets every ball of bs at the same instant. */
  hitTogether(a: string, bs: readonly string[]): this {
    const t = this.tick();
    for (const b of bs) this.events.push({ t, kind: 'ball', balls: [a, b] });
    return this;
  }

  /** id meets a cushion, n times (each at a fresh instant). */
  cushion(id: string, n = 1): this {
    for (let i = 0; i < n; i++) this.events.push({ t: this.tick(), kind: 'cushion', balls: [id] });
    return this;
  }

  /** Several balls meet cushions, one each. */
  cushions(ids: readonly string[]): this {
    for (const id of ids) this.cushion(id);
    return this;
  }

  /** id drops into a pocket. */
  pot(id: string, pocket: PocketId | string = 'TL'): this {
    this.events.push({ t: this.tick(), kind: 'pocket', balls: [id], pocket });
    this.pockets.set(id, pocket);
    return this;
  }

  /** Final resting place of id. */
  move(id: string, x: number, y: number): this {
    this.finals.set(id, { x, y });
    return this;
  }

  /** Push a raw event at a given time. */
  event(e: OutcomeEvent): this {
    this.events.push(e);
    return this;
  }

  build(): Outcome {
    const balls = this.start.map((b) => {
      const f = this.finals.get(b.id) ?? { x: b.x, y: b.y };
      const pocketed = this.pockets.has(b.id);
      const pocket = this.pockets.get(b.id);
      return pocketed ? { id: b.id, x: f.x, y: f.y, pocketed, pocket } : { id: b.id, x: f.x, y: f.y, pocketed: false };
    });
    return { balls, events: [...this.events].sort((a, b) => a.t - b.t) };
  }
}

export function outcome(start: Game | readonly Ball[]): OutcomeBuilder {
  return new OutcomeBuilder(start);
}

/** A shot by the player on turn with the ball he must strike, and any declarations. */
export function shotFor(game: Game, extra: Partial<Shot> = {}): Shot {
  return { player: game.turn, ball: cueBallId(game), heading: 0, speed: 2, side: 0, top: 0, ...extra };
}

/** A deep copy of a game with some fields replaced (Game is plain data; tests may set up positions). */
export function withState<G extends Game>(game: G, patch: Partial<G>): G {
  return { ...structuredClone(game), ...structuredClone(patch) };
}

/** Deep-frozen copy, to prove that the referees do not write into their inputs. */
export function deepFreeze<T>(value: T): T {
  if (value && typeof value === 'object') {
    for (const v of Object.values(value as Record<string, unknown>)) deepFreeze(v);
    Object.freeze(value);
  }
  return value;
}

/** Asserts that fn throws a RuleError with the given code. */
export function expectRuleError(fn: () => unknown, code: string): void {
  try {
    fn();
  } catch (e) {
    expect(e).toBeInstanceOf(RuleError);
    expect((e as RuleError).code).toBe(code);
    return;
  }
  throw new Error(`expected a RuleError ${code}`);
}
