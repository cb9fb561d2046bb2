// FNV-1a 64 over a canonical encoding of the final state: every ball in scene order (id, pocketed,
// pocket, x, y as IEEE-754 doubles, little-endian, -0 turned to 0), then the duration and the
// number of events. Equal hashes mean equal bits.
import type { FinalBall } from './sim-types.ts';

const OFFSET = 0xcbf29ce484222325n;
const PRIME = 0x100000001b3n;
const MASK = 0xffffffffffffffffn;

class Fnv64 {
  private h = OFFSET;
  private readonly view = new DataView(new ArrayBuffer(8));

  byte(b: number): void {
    this.h = ((this.h ^ BigInt(b & 0xff)) * PRIME) & MASK;
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
    return this.h.toString(16).padStart(16, '0');
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
