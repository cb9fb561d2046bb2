// FNV-1a 64 over a canonical encoding of the final state: every ball in scene order (id, pocketed,
// pocket, x, y as IEEE-754 doubles, little-endian, -0 turned to 0), then the duration and the
// number of events. Equal hashes mean equal bits.
import type { FinalBall } from './sim-types.ts';

const TWO_32 = 4294967296;

/**
 * FNV-1a 64 on two 32-bit halves held in doubles: every product below stays under 2^53, so the
 * arithmetic is exact on every engine (no BigInt on the hot path).
 */
class Fnv64 {
  private hi = 0xcbf29ce4;
  private lo = 0x84222325;
  private readonly view = new DataView(new ArrayBuffer(8));

  byte(b: number): void {
    const lo = (this.lo ^ (b & 0xff)) >>> 0;
    // (hi·2^32 + lo) · (0x100·2^32 + 0x1b3) mod 2^64
    const a = lo * 0x1b3;
    const newLo = a % TWO_32;
    const carry = (a - newLo) / TWO_32;
    this.hi = (this.hi * 0x1b3 + lo * 0x100 + carry) % TWO_32;
    this.lo = newLo;
  }

  text(s: string): void {
    for (let i = 0; i < s.length; i++) {
      const c = s.charCodeAt(i);
      this.byte(c & 0xff);
      this.byte(c >> 8);
    }
    this.byte(0);
  }

  number(x: number): void {
    this.view.setFloat64(0, x === 0 ? 0 : x, true);
    for (let i = 0; i < 8; i++) this.byte(this.view.getUint8(i));
  }

  hex(): string {
    return this.hi.toString(16).padStart(8, '0') + this.lo.toString(16).padStart(8, '0');
  }
}

export function hashFinalState(balls: readonly FinalBall[], duration: number, eventCount: number): string {
  const f = new Fnv64();
  for (const b of balls) {
    f.text(b.id);
    f.byte(b.pocketed ? 1 : 0);
    f.text(b.pocket ?? '');
    f.number(b.x);
    f.number(b.y);
  }
  f.number(duration);
  f.number(eventCount);
  return f.hex();
}
