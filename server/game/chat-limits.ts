// Chat limits: per player across all their tabs, and per room, so that neither many tabs nor many
// players can flood a room's spectators. A line is let through only when both have room for it.
import { CHAT_PER_ROOM, CHAT_WINDOW_S } from '../../shared/protocol/index.ts';
import { TokenBucket } from '../token-bucket.ts';
import { ServiceError } from './errors.ts';
import { MemoryChatLimit, type ChatLimit } from '../cluster/index.ts';

export class ChatLimits {
  private readonly rooms = new Map<string, TokenBucket>();

  /** `players`: each player's allowance, in this process or (several processes) one shared in Redis. */
  constructor(private readonly players: ChatLimit = new MemoryChatLimit()) {}

  /**
   * Counts a line from `player` in `room`, or refuses it with 'rate-limited' and how long to wait.
   * The room's allowance stays here, as a room's lines all pass its owner, one at a time.
   */
  async take(player: string, room: string, now: number): Promise<void> {
    const theirs = bucket(this.rooms, room, CHAT_PER_ROOM, now);
    const roomWait = theirs.waitMs(now);
    // The player's allowance counts the line as it answers, so it is asked only when the room has room.
    const myWait = roomWait > 0 ? 0 : await this.players.take(player, now);
    const wait = Math.max(myWait, roomWait);
    if (wait > 0) {
      const who = myWait > 0 ? 'you are sending messages too fast' : 'this room is receiving messages too fast';
      throw new ServiceError('rate-limited', `${who}; wait ${Math.ceil(wait / 1000)} s`);
    }
    theirs.take(now);
  }

  /** Forgets the buckets that have filled up again, so that the maps hold only recent talkers. */
  prune(now: number): void {
    for (const [key, b] of this.rooms) if (b.full(now)) this.rooms.delete(key);
    this.players.prune?.(now);
  }
}

function bucket(map: Map<string, TokenBucket>, key: string, lines: number, now: number): TokenBucket {
  let b = map.get(key);
  if (!b) map.set(key, (b = new TokenBucket(lines / CHAT_WINDOW_S, lines, now)));
  return b;
}
