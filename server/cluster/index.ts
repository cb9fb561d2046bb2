// The multi-process mode's shared parts (docs/scale.md): room leases and connection ids, each
// with a one-process implementation and a Redis one.
export { MemoryConnIds, RedisConnIds, type ConnIds } from './conn-ids.ts';
export { CONN_ID_KEY, PREFIX, roomOwnerKey } from './keys.ts';
export { MemoryLeases, RedisLeases, type RoomLeases } from './leases.ts';
