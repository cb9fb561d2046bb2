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

/** A read-only list of coefficients: an array or a typed array. */
export type Coefficients = ArrayLike<number>;

/** p(t) by Horner's rule. */
export function evalPoly(c: Coefficients, t: number): number {
  let v = 0;
  for (let i = c.length - 1; i >= 0; i--) v = v * t + c[i]!;
  return v;
}

/** The true degree: the index of the highest non-zero coefficient (0 for a constant). */
function degreeOf(c: Coefficients): number {
  let n = c.length - 1;
  while (n > 0 && c[n] === 0) n--;
  return n;
}

/** p(t) over the first n + 1 coefficients. */
function evalDeg(c: Coefficients, n: number, t: number): number {
  let v = 0;
  for (let i = n; i >= 0; i--) v = v * t + c[i]!;
  return v;
}

/**
 * Refines a root of p (degree n) inside [a, b] where p(a) and p(b) have opposite signs (or one is
 * zero) and p is monotonic: Newton's method kept inside the bracket (a step that would leave it
 * bisects instead), which converges quadratically; once a step is below the tolerance the bracket
 * is closed around it with two probes. Returns the end on the side of a (refinedHi holds the
 * other); the bracket is at most `tol` wide.
 */
let refinedHi = 0;
function refine(c: Coefficients, n: number, a: number, b: number, fa: number, fb: number, tol: number): number {
  let x = (a * fb - b * fa) / (fb - fa);
  if (!(x > a && x < b)) x = 0.5 * (a + b);
  for (let i = 0; i < 100 && b - a > tol; i++) {
    // p(x) and p'(x) together by Horner's rule.
    let f = 0;
    let d = 0;
    for (let k = n; k >= 0; k--) {
      d = d * x + f;
      f = f * x + c[k]!;
    }
    if (f === 0) {
      refinedHi = x;
      return x;
    }
    if (f > 0 === fa > 0) {
      a = x;
      fa = f;
    } else {
      b = x;
      fb = f;
    }
    let next = x - f / d;
    if (!(next > a && next < b) || i % 8 === 7) next = 0.5 * (a + b);
    if (Math.abs(next - x) < 0.5 * tol) {
      // Converged: close the bracket with probes either side of the estimate.
      const lo = Math.max(a, next - 0.5 * tol);
      const hi = Math.min(b, next + 0.5 * tol);
      const flo = evalDeg(c, n, lo);
      if (flo === 0) {
        refinedHi = lo;
        return lo;
      }
      if (flo > 0 === fa > 0) {
        a = lo;
        fa = flo;
        const fhi = evalDeg(c, n, hi);
        if (fhi > 0 === fa > 0 && fhi !== 0) a = hi;
        else b = hi;
      } else {
        b = lo;
      }
      x = 0.5 * (a + b);
      continue;
    }
    x = next;
  }
  refinedHi = b;
  return a;
}

/** Refines a bracketed root of a monotonic piece: [lo, hi], lo on the side of a. */
export function refineBracket(c: Coefficients, a: number, b: number, fa: number, fb: number, tol: number): [number, number] {
  const lo = refine(c, degreeOf(c), a, b, fa, fb, tol);
  return [lo, refinedHi];
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

/** Roots of a + b t + c t^2 strictly inside (lo, hi), ascending, into out; returns how many. */
function quadraticIn(a: number, b: number, c: number, lo: number, hi: number, out: Float64Array, at: number): number {
  if (c === 0) {
    if (b === 0) return 0;
    const t = -a / b;
    if (t > lo && t < hi) {
      out[at] = t;
      return 1;
    }
    return 0;
  }
  const disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const q = -0.5 * (b + (b >= 0 ? Math.sqrt(disc) : -Math.sqrt(disc)));
  let r1: number;
  let r2: number;
  if (q === 0) {
    r1 = 0;
    r2 = 0;
  } else {
    r1 = q / c;
    r2 = a / q;
    if (r2 < r1) [r1, r2] = [r2, r1];
  }
  let k = 0;
  if (r1 > lo && r1 < hi) out[at + k++] = r1;
  if (r2 > lo && r2 < hi && r2 !== r1) out[at + k++] = r2;
  return k;
}

// Scratch space, so that finding event times allocates nothing.
const DERIV = new Float64Array(4);
const CRIT = new Float64Array(4);
const CRIT_OF_CUBIC = new Float64Array(2);

/** Sign changes of a cubic (degree <= 3 in d[0..3]) strictly inside (lo, hi), ascending, into out. */
function cubicSignChanges(d: Float64Array, lo: number, hi: number, out: Float64Array): number {
  const n = degreeOf(d);
  if (n <= 2) return n === 0 ? 0 : quadraticIn(d[0]!, d[1]!, n === 2 ? d[2]! : 0, lo, hi, out, 0);
  const m = quadraticIn(d[1]!, 2 * d[2]!, 3 * d[3]!, lo, hi, CRIT_OF_CUBIC, 0);
  let k = 0;
  let a = lo;
  let fa = evalDeg(d, 3, a);
  for (let i = 0; i <= m; i++) {
    const b = i < m ? CRIT_OF_CUBIC[i]! : hi;
    const fb = evalDeg(d, 3, b);
    if (fa !== 0 && fb !== 0 && fa > 0 !== fb > 0) {
      const l = refine(d, 3, a, b, fa, fb, 1e-15 * Math.max(1, Math.abs(b)));
      out[k++] = 0.5 * (l + refinedHi);
    } else if (fb === 0 && i < m) {
      out[k++] = b;
    }
    a = b;
    fa = fb;
  }
  return k;
}

/** Points strictly inside (lo, hi) where p (degree n <= 4) may turn, ascending, into CRIT. */
function criticalPoints(c: Coefficients, n: number, lo: number, hi: number): number {
  if (n <= 1) return 0;
  if (n === 2) return quadraticIn(c[1]!, 2 * c[2]!, 0, lo, hi, CRIT, 0);
  if (n === 3) return quadraticIn(c[1]!, 2 * c[2]!, 3 * c[3]!, lo, hi, CRIT, 0);
  DERIV[0] = c[1]!;
  DERIV[1] = 2 * c[2]!;
  DERIV[2] = 3 * c[3]!;
  DERIV[3] = 4 * c[4]!;
  return cubicSignChanges(DERIV, lo, hi, CRIT);
}

/** Every sign change of p (degree <= 4) in [lo, hi], ascending (each refined to a narrow bracket's midpoint). */
export function rootsIn(c: Coefficients, lo: number, hi: number): number[] {
  const n = degreeOf(c);
  const m = criticalPoints(c, n, lo, hi);
  const points = [lo, ...Array.from(CRIT.subarray(0, m)), hi];
  const roots: number[] = [];
  let a = points[0]!;
  let fa = evalDeg(c, n, a);
  for (let i = 1; i < points.length; i++) {
    const b = points[i]!;
    const fb = evalDeg(c, n, b);
    if (fa === 0) {
      if (roots.length === 0 || roots[roots.length - 1] !== a) roots.push(a);
    } else if (fb !== 0 && fa > 0 !== fb > 0) {
      const l = refine(c, n, a, b, fa, fb, 1e-15 * Math.max(1, Math.abs(b)));
      roots.push(0.5 * (l + refinedHi));
    }
    a = b;
    fa = fb;
  }
  if (fa === 0 && roots[roots.length - 1] !== a) roots.push(a);
  return roots;
}

/**
 * The first time in [lo, hi] at which p (degree <= 4), positive at lo, reaches zero or below: the
 * moment two bodies whose squared gap p measures come into contact. Returns the last time found
 * with p still >= 0 (so the bodies never overlap at the event), or Infinity when p stays positive.
 * Tangencies where p just touches zero count as contact; a critical point where p dips to <= 0 is
 * found even when p is positive at both ends. Allocates nothing.
 */
export function firstEntry(c: Coefficients, lo: number, hi: number, tol: number): number {
  const n = degreeOf(c);
  let a = lo;
  let fa = evalDeg(c, n, a);
  if (!(fa > 0)) return lo;
  const m = criticalPoints(c, n, lo, hi);
  for (let i = 0; i <= m; i++) {
    const b = i < m ? CRIT[i]! : hi;
    const fb = evalDeg(c, n, b);
    if (fb <= 0) return refine(c, n, a, b, fa, fb, tol);
    a = b;
    fa = fb;
  }
  return Infinity;
}
