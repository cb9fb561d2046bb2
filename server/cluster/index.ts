// The Redis building blocks of the multi-process mode (docs/scale.md): each an interface, an
// in-memory implementation for one process and a Redis one for many.
export { KEYS, requireId, requireMs } from './keys.ts';
export { connectRedis, type RedisClient } from './redis.ts';
export { MemoryConnIds, RedisConnIds, type ConnIds } from './conn-ids.ts';
export { MemoryRoomLeases, RedisRoomLeases, type RoomLeases } from './leases.ts';
export { MemoryChatLimit, RedisChatLimit, type ChatLimit } from './chat-limit.ts';
export { MemoryBus, RedisBus, parseEnvelope, type Bus, type BusHandler, type BusMessage } from './bus.ts';
export { RedisRegistry, type PresenceEntry } from './registry.ts';
export { ClusterNode, CLUSTER_TIMING, type ClusterTiming, type Peers } from './node.ts';
