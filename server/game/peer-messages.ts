// The messages between the game services of several processes (docs/scale.md), checked with
// valibot as they arrive: a command forwarded to a room's owner, deliveries for a process's
// sockets (`ref` answers a forwarded command), a room's state as its owner committed it, and
// presence events.
import * as v from 'valibot';
import { ClientMessageSchema } from '../../shared/protocol/index.ts';

const Conn = v.pipe(v.number(), v.safeInteger(), v.minValue(0));
const Player = v.object({ id: v.pipe(v.string(), v.minLength(1)), name: v.string() });
const Ref = v.pipe(v.number(), v.safeInteger(), v.minValue(1));

export const PeerMessageSchema = v.variant('t', [
  v.object({ t: v.literal('cmd'), ref: Ref, conn: Conn, player: Player, msg: ClientMessageSchema }),
  v.object({ t: v.literal('out'), ref: v.optional(Ref), deliveries: v.pipe(v.array(v.object({ to: v.pipe(v.array(Conn), v.readonly()), message: v.looseObject({ type: v.string() }) })), v.readonly()) }),
  v.object({
    t: v.literal('room'),
    state: v.looseObject({ id: v.pipe(v.string(), v.minLength(1)), stateId: v.pipe(v.number(), v.safeInteger()), status: v.picklist(['waiting', 'playing', 'over', 'closed']), seats: v.pipe(v.array(Player), v.readonly()) }),
    spectators: v.pipe(v.array(Conn), v.readonly()),
    outcome: v.nullable(v.object({ rated: v.boolean(), unrated: v.nullable(v.string()) })),
  }),
  v.object({ t: v.literal('attach'), conn: Conn, player: Player }),
  v.object({ t: v.literal('detach'), conn: Conn }),
  v.object({ t: v.literal('rename'), player: Player }),
]);

export type PeerMessage = v.InferOutput<typeof PeerMessageSchema>;
