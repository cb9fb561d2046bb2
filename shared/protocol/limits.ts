// The protocol's limits, shared by the server (which enforces them) and the client (which respects them).

/** Largest WebSocket frame a client may send (bytes); a larger one closes the socket with 1009. */
export const MAX_FRAME_BYTES = 8 * 1024;
/** A player's name: 1 to 32 characters, plain text. */
export const NAME_MAX = 32;
/** A chat line: 1 to 200 characters, plain text. */
export const CHAT_MAX = 200;
/** Longest shot clock a room may set (s); 0 is no clock. */
export const SHOT_CLOCK_MAX_S = 600;
/** Shortest shot clock (s): a clock must leave time to aim, and a shorter one fouls on every tick. */
export const SHOT_CLOCK_MIN_S = 10;
/** Largest race a room may set (racks, frames or points). */
export const RACE_MAX = 50;
/** Open rooms (waiting or playing) one player may have created at once. */
export const MAX_OPEN_ROOMS_PER_PLAYER = 5;
/** Messages a socket may send: a token bucket of this many a second with bursts up to RATE_BURST. */
export const RATE_PER_SECOND = 20;
export const RATE_BURST = 40;
/** Chat lines one player may send (across all their tabs), and one room may carry, in CHAT_WINDOW_S seconds. */
export const CHAT_PER_PLAYER = 5;
export const CHAT_PER_ROOM = 20;
export const CHAT_WINDOW_S = 10;
/** Rooms listed in a `lobby` message (waiting rooms first); `more` counts the rest. */
export const LOBBY_MAX_ROOMS = 200;
/** Lobby updates go to subscribers at most once in this many ms (the latest list). */
export const LOBBY_UPDATE_MS = 1000;
/** Default caps the server's environment may change: sockets open at once per player (tabs). */
export const MAX_TABS_PER_PLAYER = 10;
/** WebSocket close codes the server uses. */
export const CLOSE_TOO_BIG = 1009;
export const CLOSE_POLICY = 1008;

/** The computer's levels run from 1 to this (shared/ai). */
export const COMPUTER_LEVEL_MAX = 5;
