// What a client may send: one valibot schema per message, joined on `type`. The server parses every
// frame with these and the browser client builds its messages to them, so both share one definition.
// Unknown extra fields are dropped; numbers must be finite; strings and arrays are bounded.
import * as v from 'valibot';
import { CHAT_MAX, COMPUTER_LEVEL_MAX, NAME_MAX, RACE_MAX, SHOT_CLOCK_MAX_S, SHOT_CLOCK_MIN_S } from './limits.ts';
import { graphemeCount, plainTextProblem } from './text.ts';

/** A request id, echoed as `re` by the reply or error it causes. */
const RequestId = v.optional(v.union([v.pipe(v.string(), v.maxLength(64)), v.pipe(v.number(), v.finite())]));
const RoomId = v.pipe(v.string(), v.minLength(1), v.maxLength(64));
const StateId = v.pipe(v.number(), v.integer(), v.minValue(0));
/** A finite number within ±limit: anything larger is never a sane position, angle or speed. */
const bounded = (limit: number) => v.pipe(v.number(), v.finite(), v.minValue(-limit), v.maxValue(limit));
const BallId = v.pipe(v.string(), v.minLength(1), v.maxLength(16));

export const GAME_KINDS = ['nineball', 'eightball', 'snooker', 'threecushion'] as const;
export const GameKindSchema = v.picklist(GAME_KINDS);
/** Guidance a room allows: none, the aim to first contact, or the cue ball's whole predicted path. */
export const GUIDANCE = ['none', 'contact', 'path'] as const;

/** Plain text: no control characters (markup is harmless, as clients never render text as HTML). */
/**
 * Text of 1 to `max` characters as people count them (graphemes: a flag or a family emoji is one),
 * plain (shared/protocol/text.ts). The cap in UTF-16 code units only bounds the work: 20 a
 * character is more than any emoji sequence needs.
 */
const plainText = (max: number) =>
  v.pipe(
    v.string(),
    v.trim(),
    v.minLength(1, 'must not be empty'),
    v.maxLength(max * 20, `must be at most ${max} characters (and ${max * 20} UTF-16 code units)`),
    v.check((s) => graphemeCount(s) <= max, (i) => `must be at most ${max} characters; this has ${graphemeCount(i.input as string)}`),
    v.rawCheck(({ dataset, addIssue }) => {
      const problem = dataset.typed ? plainTextProblem(dataset.value) : undefined;
      if (problem !== undefined) addIssue({ message: problem });
    }),
  );

export const PointSchema = v.object({ x: bounded(10), y: bounded(10) });

export const ShotSchema = v.object({
  ball: BallId,
  heading: bounded(1000),
  speed: v.pipe(v.number(), v.finite(), v.minValue(0), v.maxValue(20)),
  side: bounded(1),
  top: bounded(1),
  pushOut: v.optional(v.boolean()),
  calledPocket: v.optional(v.picklist(['BL', 'BR', 'ML', 'MR', 'TL', 'TR'])),
  calledBall: v.optional(BallId),
  nominated: v.optional(BallId),
});

export const HelloSchema = v.object({
  type: v.literal('hello'),
  id: RequestId,
  name: v.optional(plainText(NAME_MAX)),
  token: v.optional(v.pipe(v.string(), v.minLength(1), v.maxLength(128))),
});
/** The lobby now; `watch` (default true) keeps its updates coming, `watch: false` stops them. */
export const LobbySchema = v.object({ type: v.literal('lobby'), id: RequestId, watch: v.optional(v.boolean()) });
export const CreateSchema = v.object({
  type: v.literal('create'),
  id: RequestId,
  kind: GameKindSchema,
  raceTo: v.optional(v.pipe(v.number(), v.integer(), v.minValue(1), v.maxValue(RACE_MAX))),
  private: v.optional(v.boolean()),
  shotClock: v.optional(
    v.pipe(
      v.number(),
      v.finite(),
      v.check((s) => s === 0 || (s >= SHOT_CLOCK_MIN_S && s <= SHOT_CLOCK_MAX_S), `must be 0 (no clock) or from ${SHOT_CLOCK_MIN_S} to ${SHOT_CLOCK_MAX_S} seconds`),
    ),
  ),
  /** How much the players' pages may show of a shot before it is played (default 'contact'). */
  guidance: v.optional(v.picklist(GUIDANCE)),
  /** Play the computer at this level (1 to 5): it takes the second seat and the game starts at once. */
  computer: v.optional(
    v.pipe(
      v.number('must be a level from 1 to 5 (a whole number)'),
      v.check((n) => Number.isInteger(n) && n >= 1 && n <= COMPUTER_LEVEL_MAX, `must be a level from 1 to ${COMPUTER_LEVEL_MAX} (a whole number)`),
    ),
  ),
});
export const RenameSchema = v.object({ type: v.literal('rename'), id: RequestId, name: plainText(NAME_MAX) });
const roomCommand = <T extends string>(type: T) => v.object({ type: v.literal(type), id: RequestId, room: RoomId });
export const JoinSchema = roomCommand('join');
export const WatchSchema = roomCommand('watch');
export const LeaveSchema = roomCommand('leave');
export const ConcedeSchema = roomCommand('concede');
export const RematchSchema = roomCommand('rematch');
export const ClaimSchema = roomCommand('claim');
export const ShotMessageSchema = v.object({
  type: v.literal('shot'),
  id: RequestId,
  room: RoomId,
  stateId: StateId,
  shot: ShotSchema,
  cueBall: v.optional(PointSchema),
});
export const PlaceSchema = v.object({ type: v.literal('place'), id: RequestId, room: RoomId, stateId: StateId, cueBall: PointSchema });
export const DecideSchema = v.object({
  type: v.literal('decide'),
  id: RequestId,
  room: RoomId,
  stateId: StateId,
  choice: v.picklist(['pass', 'rerack', 'rerack-other']),
});
export const ChatSchema = v.object({ type: v.literal('chat'), id: RequestId, room: RoomId, text: plainText(CHAT_MAX) });

export const ClientMessageSchema = v.variant('type', [
  HelloSchema,
  RenameSchema,
  LobbySchema,
  CreateSchema,
  JoinSchema,
  WatchSchema,
  LeaveSchema,
  ShotMessageSchema,
  PlaceSchema,
  DecideSchema,
  ConcedeSchema,
  RematchSchema,
  ClaimSchema,
  ChatSchema,
]);

export type ClientMessage = v.InferOutput<typeof ClientMessageSchema>;
export type ClientMessageType = ClientMessage['type'];
export type ShotInput = v.InferOutput<typeof ShotSchema>;
export type GameKindName = v.InferOutput<typeof GameKindSchema>;
