// Random scenes for property tests: balls scattered on a table, some in frozen clusters.
import { tableSpec, type SceneBall, type TableName } from '../../shared/physics/index.ts';
import { generator, randomBalls } from '../../shared/scenes/index.ts';

/** `count` balls from `seed`; with `frozen`, each ball after the first is placed touching the one before when it fits. */
export function randomScene(table: TableName, count: number, seed: number, frozen: boolean): SceneBall[] {
  const next = generator(seed);
  const balls = randomBalls(table, count, next);
  if (!frozen || balls.length < 2) return balls;
  const spec = tableSpec(table);
  const R = spec.ballRadius;
  const out: SceneBall[] = [balls[0]!];
  for (let i = 1; i < balls.length; i++) {
    const a = next() * 2 * Math.PI;
    const p = out[out.length - 1]!;
    const c = { id: balls[i]!.id, x: p.x + 2 * R * Math.cos(a), y: p.y + 2 * R * Math.sin(a) };
    const fits = Math.abs(c.x) <= spec.length / 2 - R && Math.abs(c.y) <= spec.width / 2 - R && out.every((o) => Math.hypot(o.x - c.x, o.y - c.y) >= 2 * R - 1e-10);
    const fallback = balls[i]!;
    const clear = out.every((o) => Math.hypot(o.x - fallback.x, o.y - fallback.y) >= 2 * R - 1e-10);
    if (fits) out.push(c);
    else if (clear) out.push(fallback);
  }
  return out;
}
