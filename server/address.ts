// Which clients count as one place, for every limit per address (sockets, new guests, practice
// requests): an IPv4 address (also when written as IPv6 ::ffff:a.b.c.d), or an IPv6 /64, which one
// home or one host usually holds whole, so that an attacker cannot step round a limit with the
// addresses of their own prefix. No address at all (a socket already gone) is 'unknown'.
import { isIPv6 } from 'node:net';

export function addressKey(remote: string | undefined): string {
  if (!remote) return 'unknown';
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
