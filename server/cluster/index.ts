// The Redis building blocks of the multi-process mode (docs/scale.md), each behind an interface;
// the chat limit also has the in-memory form one process uses.
export { KEYS, requireId, requireMs } from './keys.ts';
export { connectRedis, type RedisClient } from './redis.ts';
export { RedisConnIds, type ConnIds } from './conn-ids.ts';
export { RedisRoomLeases, type RoomLeases } from './leases.ts';
export { MemoryChatLimit, RedisChatLimit, type ChatLimit } from './chat-limit.ts';
export { RedisBus, parseEnvelope, type Bus, type BusHandler, type BusMessage } from './bus.ts';
export { RedisRegistry, type PresenceEntry } from './registry.ts';
export { ClusterNode, CLUSTER_TIMING, type ClusterTiming, type Peers } from './node.ts';
