// Robust real roots of polynomials of degree <= 4 on an interval, for event times.
//
// Closed-form quartic formulas lose most of their digits exactly where billiards lives (touching
// balls, grazing contacts, equal accelerations that make the leading coefficients vanish). Instead
// each polynomial is cut into monotonic pieces at the roots of its derivative (found the same way,
// recursively, down to a quadratic solved in closed form), and a sign change on a monotonic piece
// is refined by a bracketing method that never leaves its bracket. No root is skipped: between two
// consecutive critical points the polynomial is monotonic, so it has at most one root there.
//
// Coefficients are in ascending order: p(t) = c[0] + c[1] t + c[2] t^2 + ...

/** p(t) by Horner's rule. */
export function evalPoly(c: readonly number[], t: number): number {
  let v = 0;
  for (let i = c.length - 1; i >= 0; i--) v = v * t + c[i]!;
  return v;
}

function derivative(c: readonly number[]): number[] {
  const d: number[] = [];
  for (let i = 1; i < c.length; i++) d.push(i * c[i]!);
  return d;
}

/** Drops leading coefficients that are zero, so the degree is the true one. */
function trimmed(c: readonly number[]): number[] {
  let n = c.length;
  while (n > 1 && c[n - 1] === 0) n--;
  return c.slice(0, n);
}

/**
 * Refines a root of p inside [a, b] where p(a) and p(b) have opposite signs (or one is zero) and p
 * is monotonic. The Illinois variant of regula falsi (Dowell and Jarratt 1971) converges
 * superlinearly; a bisection step is taken whenever it stalls. Returns [lo, hi], a bracket of width
 * at most `tol` with lo on the side of a.
 */
export function refineBracket(c: readonly number[], a: number, b: number, fa: number, fb: number, tol: number): [number, number] {
  let side = 0;
  for (let i = 0; i < 200 && b - a > tol; i++) {
    let m: number;
    if (i % 3 === 2) {
      m = 0.5 * (a + b); // a guaranteed halving every third step keeps the worst case bounded
    } else {
      m = (a * fb - b * fa) / (fb - fa);
      if (!(m > a && m < b)) m = 0.5 * (a + b);
    }
    const fm = evalPoly(c, m);
    if (fm === 0) return [m, m];
    if ((fm > 0) === (fa > 0)) {
      a = m;
      fa = fm;
      if (side === 1) fb *= 0.5;
      side = 1;
    } else {
      b = m;
      fb = fm;
      if (side === -1) fa *= 0.5;
      side = -1;
    }
  }
  return [a, b];
}

/** Points where the derivative changes sign strictly inside (lo, hi), ascending. */
function criticalPoints(c: readonly number[], lo: number, hi: number): number[] {
  const d = trimmed(derivative(c));
  const deg = d.length - 1;
  if (deg <= 0) return [];
  if (deg === 1) {
    const t = -d[0]! / d[1]!;
    return t > lo && t < hi ? [t] : [];
  }
  if (deg === 2) return quadraticRoots(d[0]!, d[1]!, d[2]!).filter((t) => t > lo && t < hi);
  return rootsIn(d, lo, hi);
}

/** Real roots of a + b t + c t^2 (c != 0), ascending, without cancellation (Press et al. 5.6). */
export function quadraticRoots(a: number, b: number, c: number): number[] {
  const disc = b * b - 4 * a * c;
  if (disc < 0) return [];
  const q = -0.5 * (b + (b >= 0 ? Math.sqrt(disc) : -Math.sqrt(disc)));
  if (q === 0) return [0, 0];
  const r1 = q / c;
  const r2 = a / q;
  return r1 < r2 ? [r1, r2] : [r2, r1];
}

/** Every sign change of p in [lo, hi], ascending (each refined to a narrow bracket's midpoint). */
export function rootsIn(c: readonly number[], lo: number, hi: number): number[] {
  const p = trimmed(c);
  const points = [lo, ...criticalPoints(p, lo, hi), hi];
  const roots: number[] = [];
  let a = points[0]!;
  let fa = evalPoly(p, a);
  for (let i = 1; i < points.length; i++) {
    const b = points[i]!;
    const fb = evalPoly(p, b);
    if (fa === 0) {
      if (roots.length === 0 || roots[roots.length - 1] !== a) roots.push(a);
    } else if (fb !== 0 && (fa > 0) !== (fb > 0)) {
      const [l, h] = refineBracket(p, a, b, fa, fb, 1e-15 * Math.max(1, Math.abs(b)));
      roots.push(0.5 * (l + h));
    }
    a = b;
    fa = fb;
  }
  if (fa === 0 && roots[roots.length - 1] !== a) roots.push(a);
  return roots;
}

/**
 * The first time in [lo, hi] at which p, positive at lo, reaches zero or below: the moment two
 * bodies whose squared gap p measures come into contact. Returns the last time found with p still
 * >= 0 (so the bodies never overlap at the event), or Infinity when p stays positive. Tangencies
 * where p just touches zero count as contact; a critical point where p dips to <= 0 is found even
 * when p is positive at both ends.
 */
export function firstEntry(c: readonly number[], lo: number, hi: number, tol: number): number {
  const p = trimmed(c);
  let a = lo;
  let fa = evalPoly(p, a);
  if (!(fa > 0)) return lo;
  const crit = criticalPoints(p, lo, hi);
  for (let i = 0; i <= crit.length; i++) {
    const b = i < crit.length ? crit[i]! : hi;
    const fb = evalPoly(p, b);
    if (fb <= 0) return refineBracket(p, a, b, fa, fb, tol)[0];
    a = b;
    fa = fb;
  }
  return Infinity;
}
