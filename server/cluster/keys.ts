// The Redis keys of the multi-process mode, all under one prefix (docs/scale.md lists them).
export const PREFIX = 'baize:';

/** A room's owner: the id of the process holding its lease (a string with a TTL). */
export const roomOwnerKey = (roomId: string): string => `${PREFIX}room:${roomId}:owner`;

/** The counter connection ids are taken from, in blocks. */
export const CONN_ID_KEY = `${PREFIX}conn-ids`;

/** Ids are 1 to 32 characters of letters, digits, '_' and '-' (room ids, process ids). */
export function checkId(what: string, id: unknown): string {
  if (typeof id !== 'string' || !/^[A-Za-z0-9_-]{1,32}$/.test(id)) {
    throw new RangeError(`${what} must be 1 to 32 letters, digits, '_' or '-', got ${JSON.stringify(id)}`);
  }
  return id;
}
