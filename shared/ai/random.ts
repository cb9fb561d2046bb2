// The computer's own random draws, from its seed alone (never the game's generator, which the
// rules own): the rules' xorshift32, and a Gaussian as the sum of twelve uniforms less six
// (Irwin-Hall: mean 0, variance 1), which needs no log or cos and so is exact on every engine.
import { nextUint32, seedState } from '../rules/index.ts';

export class Random {
  private state: number;
  constructor(seed: number | string) {
    this.state = seedState(seed);
  }
  /** Uniform in [0, 1). */
  uniform(): number {
    const r = nextUint32(this.state);
    this.state = r.state;
    return r.value / 0x100000000;
  }
  /** Standard normal, approximately (Irwin-Hall of 12, tails cut at 6 sigma). */
  gaussian(): number {
    let s = 0;
    for (let i = 0; i < 12; i++) s += this.uniform();
    return s - 6;
  }
}
