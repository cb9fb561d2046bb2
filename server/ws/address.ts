// Which connections count as coming from one place, for limits per address: an IPv4 address (also
// when written as IPv6 ::ffff:a.b.c.d), or an IPv6 /64, which one home or one host usually holds
// whole, so that an attacker cannot step round the limit with the addresses of their own prefix.
import { isIPv6 } from 'node:net';
import type { VerifyClientCallbackAsync } from 'ws';

export function addressKey(remote: string): string {
  const address = remote.split('%', 1)[0]!.toLowerCase();
  const mapped = /^::ffff:(\d+\.\d+\.\d+\.\d+)$/.exec(address);
  if (mapped) return mapped[1]!;
  if (!isIPv6(address)) return address;
  return `${expand(address).slice(0, 4).join(':')}::/64`;
}

/** The eight groups of an IPv6 address, '::' filled in (an embedded IPv4 tail counts as two). */
function expand(address: string): string[] {
  const [head, tail] = address.includes('::') ? address.split('::') : [address, undefined];
  const groups = (part: string | undefined) => (part ? part.split(':').flatMap((g) => (g.includes('.') ? ['0', '0'] : [g])) : []);
  const left = groups(head);
  const right = groups(tail);
  const fill = tail === undefined ? [] : Array<string>(8 - left.length - right.length).fill('0');
  return [...left, ...fill, ...right].map((g) => g.replace(/^0+(?=.)/, ''));
}

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
