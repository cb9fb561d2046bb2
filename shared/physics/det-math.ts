// Deterministic elementary functions from + - * / only, so every JavaScript engine computes the
// same bits (ECMA-262 leaves Math.sin, cos, exp implementation-approximated). Accuracy is a few
// ulp on the ranges the physics uses, which is far below any physical tolerance; what matters is
// that the result is the same everywhere.

const TWO_PI = 6.283185307179586;
const HALF_PI = 1.5707963267948966;
// π/2 split in three parts (Cody and Waite 1980) so that x - k·π/2 loses no bits for moderate k.
const PIO2_1 = 1.5707963267341256; // first 33 bits of π/2
const PIO2_2 = 6.077100506303966e-11; // next 33 bits
const PIO2_3 = 2.0222662487959506e-21; // the rest

/** sin and cos on [-π/4, π/4] by their Taylor series to degree 17/16 (error below 1e-17). */
function sinKernel(r: number): number {
  const r2 = r * r;
  return r * (1 + r2 * (-1 / 6 + r2 * (1 / 120 + r2 * (-1 / 5040 + r2 * (1 / 362880 + r2 * (-1 / 39916800 + r2 * (1 / 6227020800 + r2 * (-1 / 1307674368000 + r2 * (1 / 355687428096000)))))))));
}
function cosKernel(r: number): number {
  const r2 = r * r;
  return 1 + r2 * (-1 / 2 + r2 * (1 / 24 + r2 * (-1 / 720 + r2 * (1 / 40320 + r2 * (-1 / 3628800 + r2 * (1 / 479001600 + r2 * (-1 / 87178291200 + r2 * (1 / 20922789888000))))))));
}

/** Reduces x to r in [-π/4, π/4] and the quadrant k mod 4, with x = r + k·π/2. */
function reduce(x: number): { r: number; q: number } {
  const k = Math.round(x / HALF_PI);
  const r = x - k * PIO2_1 - k * PIO2_2 - k * PIO2_3;
  const q = ((k % 4) + 4) % 4;
  return { r, q };
}

/**
 * Both sin and cos of x; x must be finite and is best kept within a few turns. Exactly odd and even:
 * sin(-x) is -sin(x) and cos(-x) is cos(x) to the bit, since |x| is reduced and the sign applied
 * after (reducing -x itself would round its halves, such as -3π/4 = -1.5 quadrants, the other way),
 * which makes a shot and its mirror image y -> -y bit-exact mirrors.
 */
export function sinCos(x: number): { sin: number; cos: number } {
  const { r, q } = reduce(Math.abs(x));
  const s = sinKernel(r);
  const c = cosKernel(r);
  const sign = x < 0 ? -1 : 1;
  switch (q) {
    case 0:
      return { sin: sign * s, cos: c };
    case 1:
      return { sin: sign * c, cos: -s };
    case 2:
      return { sin: -sign * s, cos: -c };
    default:
      return { sin: -sign * c, cos: s };
  }
}

export function detSin(x: number): number {
  return sinCos(x).sin;
}
export function detCos(x: number): number {
  return sinCos(x).cos;
}

/** Wraps an angle to [0, 2π). */
export function wrapAngle(x: number): number {
  const k = Math.floor(x / TWO_PI);
  const r = x - k * TWO_PI;
  return r >= TWO_PI ? 0 : r;
}

const LN2_HI = 0.6931471803691238; // ln 2 split (Cody and Waite)
const LN2_LO = 1.9082149292705877e-10;
const INV_LN2 = 1.4426950408889634;

/** e^x for x in [-700, 700]: x = k ln2 + r with |r| <= ln2/2, e^r by Taylor to degree 14. */
export function detExp(x: number): number {
  if (x > 700) return Infinity;
  if (x < -700) return 0;
  const k = Math.round(x * INV_LN2);
  const r = x - k * LN2_HI - k * LN2_LO;
  let term = 1;
  let sum = 1;
  for (let n = 1; n <= 14; n++) {
    term = (term * r) / n;
    sum += term;
  }
  // Scale by 2^k through exact multiplications by 2 or 1/2, at most 1010 of them.
  let scale = 1;
  const step = k >= 0 ? 2 : 0.5;
  for (let i = Math.abs(k); i > 0; i--) scale *= step;
  return sum * scale;
}

const PI = 3.141592653589793;
const QUARTER_PI = 0.7853981633974483;
const TAN_PI_8 = 0.41421356237309503;

/** atan(u) for |u| <= tan(π/8) by its Taylor series (terms below 1e-18 dropped). */
function atanSmall(u: number): number {
  const u2 = u * u;
  let term = u;
  let sum = u;
  for (let n = 1; n <= 22; n++) {
    term *= -u2;
    sum += term / (2 * n + 1);
  }
  return sum;
}

/** atan2(y, x) in (-π, π], deterministic: octant reduction, then atan(t) = π/4 + atan((t-1)/(t+1)). */
export function detAtan2(y: number, x: number): number {
  if (x === 0 && y === 0) return 0;
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  const swap = ay > ax;
  const t = swap ? ax / ay : ay / ax; // in [0, 1]
  let a = t > TAN_PI_8 ? QUARTER_PI + atanSmall((t - 1) / (t + 1)) : atanSmall(t);
  if (swap) a = 2 * QUARTER_PI - a;
  if (x < 0) a = PI - a;
  return y < 0 || (y === 0 && 1 / y < 0) ? -a : a;
}
