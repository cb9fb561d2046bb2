// Sockets open at once per address (server/address.ts says which clients count as one).
import type { VerifyClientCallbackAsync } from 'ws';
import { addressKey } from '../address.ts';

/**
 * Sockets open at once per address (addressKey), against one client holding thousands. One over
 * the cap is refused at the upgrade, before the WebSocket handshake (the cheapest answer to a
 * flood): HTTP 429 with the reason and Retry-After; a browser sees a failed connection and retries.
 */
export class AddressCap {
  private readonly open = new Map<string, number>();

  constructor(readonly max: number) {}

  /** ws's verifyClient hook. */
  readonly verify: VerifyClientCallbackAsync = ({ req }, done) => {
    if ((this.open.get(addressKey(req.socket.remoteAddress ?? '')) ?? 0) < this.max) done(true);
    else done(false, 429, `too many connections from your address (at most ${this.max})`, { 'Retry-After': '10' });
  };

  /** Counts a socket from `remote`; returns what uncounts it when it closes. */
  add(remote: string): () => void {
    const key = addressKey(remote);
    this.open.set(key, (this.open.get(key) ?? 0) + 1);
    return () => {
      const left = (this.open.get(key) ?? 1) - 1;
      if (left > 0) this.open.set(key, left);
      else this.open.delete(key);
    };
  }
}
