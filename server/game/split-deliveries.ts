// Several processes: one operation's deliveries split by the process holding each socket. Each
// message keeps its order; a socket this process holds (or one no process is known for) stays here.
import type { ConnId, Delivery } from './service.ts';

export interface Split {
  /** For this process's own sockets. */
  readonly here: Delivery[];
  /** For each other process, in the order the messages were made. */
  readonly there: Map<string, Delivery[]>;
}

export function splitDeliveries(out: readonly Delivery[], processOf: (conn: ConnId) => string | undefined): Split {
  const here: Delivery[] = [];
  const there = new Map<string, Delivery[]>();
  for (const d of out) {
    const mine: ConnId[] = [];
    const theirs = new Map<string, ConnId[]>();
    for (const c of d.to) {
      const proc = processOf(c);
      if (proc === undefined) mine.push(c);
      else theirs.set(proc, [...(theirs.get(proc) ?? []), c]);
    }
    if (mine.length > 0) here.push(mine.length === d.to.length ? d : { to: mine, message: d.message });
    for (const [proc, to] of theirs) there.set(proc, [...(there.get(proc) ?? []), { to, message: d.message }]);
  }
  return { here, there };
}
