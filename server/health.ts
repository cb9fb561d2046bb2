// GET /healthz: up, its version and schema, and whether the database can be written. A write is
// tried at most once a second while it succeeds; while it fails, every check tries again, so the
// answer turns back to ok as soon as the disk has room or the lock is gone. Checks that arrive
// while a write is being tried share its answer.
import type { Health } from './http-routes.ts';

export interface HealthSource {
  readonly version: string;
  schema(): Promise<number>;
  /** Rejects when the database cannot be written. */
  probeWrite(): Promise<void>;
  readonly now?: () => number;
}

/** How long a successful write vouches for the database (ms). */
export const HEALTH_CACHE_MS = 1000;

export function healthCheck(source: HealthSource): () => Promise<Health> {
  const now = source.now ?? Date.now;
  let okUntil = -Infinity;
  let probing: Promise<Health> | undefined;
  const probe = async (t: number): Promise<Health> => {
    try {
      await source.probeWrite();
      okUntil = t + HEALTH_CACHE_MS;
    } catch (err) {
      okUntil = -Infinity;
      return { ok: false, version: source.version, schema: await source.schema(), error: `the database cannot be written: ${(err as Error).message}` };
    }
    return { ok: true, version: source.version, schema: await source.schema() };
  };
  return async () => {
    const t = now();
    if (t < okUntil) return { ok: true, version: source.version, schema: await source.schema() };
    probing ??= probe(t).finally(() => {
      probing = undefined;
    });
    return probing;
  };
}
