// Types of the referees: the Game (plain JSON data), the Shot with its declarations, the Outcome
// read from the table simulation, and the Verdict of a shot. No behaviour lives here.
import type { TableName } from '../physics/tables.ts';
import type { PocketId } from './pockets.ts';

export type { TableName } from '../physics/tables.ts';
export type { PocketId } from './pockets.ts';

export type GameKind = 'nineball' | 'eightball' | 'snooker' | 'threecushion' | 'practice';
export type PlayerId = string;

/** A ball at rest on the table: metres from the table centre, x along the long side. */
export interface Ball {
  id: string;
  x: number;
  y: number;
}

export interface Point {
  x: number;
  y: number;
}

/**
 * Where the cue ball in hand may be placed: false when it is not in hand; 'anywhere' on the bed;
 * 'kitchen' behind the head string (pool); 'D' on or within the lines of the D (snooker).
 */
export type BallInHand = false | 'anywhere' | 'kitchen' | 'D';

/** The stroke as the simulation takes it (issue 4's `shot`). */
export interface StrikeParams {
  /** Id of the struck ball. */
  ball: string;
  /** Direction of travel, radians from +x, counter-clockwise. */
  heading: number;
  /** Speed of the struck ball just after the strike, m/s. */
  speed: number;
  /** Horizontal tip offset as a fraction of R, + right. */
  side: number;
  /** Vertical tip offset as a fraction of R, + above centre. */
  top: number;
}

/** A shot as the referee takes it: the stroke, who plays it, and the declarations. */
export interface Shot extends StrikeParams {
  player: PlayerId;
  /** Nine-ball only: the shot is declared a push-out (WPA 2.4). */
  pushOut?: boolean;
  /** Eight-ball only, when the 8 is the shooter's legal object ball: the called pocket (WPA 3, 1.6 call shot). */
  calledPocket?: PocketId;
  /** Eight-ball only, with calledPocket: the called ball, which can only be '8'. */
  calledBall?: string;
  /**
   * Snooker only: the nominated ball. For a free ball (WPBSA S3 R12) any ball that is not on;
   * after a red (ball on: a colour) the colour the striker nominates (WPBSA S3 R4).
   */
  nominated?: string;
}

/** One ball of the simulation's result (issue 4): final position, and whether it was pocketed. */
export interface OutcomeBall {
  id: string;
  x: number;
  y: number;
  pocketed: boolean;
  pocket?: string;
}

/** One event of the simulation's result (issue 4), in time order. */
export interface OutcomeEvent {
  t: number;
  kind: 'ball' | 'cushion' | 'pocket' | 'motion' | (string & {});
  balls: readonly string[];
  pocket?: string;
}

/**
 * The part of the simulation's result the referees read: `simulate(scene, shot)` returns a
 * superset of this (duration, hash, ...), so it can be passed in directly.
 */
export interface Outcome {
  balls: readonly OutcomeBall[];
  events: readonly OutcomeEvent[];
}

/** What the player on turn may decide instead of shooting (see decide() in index.ts). */
export type Choice =
  /** Hand the shot back: nine-ball after a push-out (WPA 2.4); snooker after a foul, the offender
   * plays again (WPBSA S3 R12); snooker re-spotted black, the winner of the lot lets the other start. */
  | 'pass'
  /** Eight-ball: re-rack, and the chooser breaks (WPA 3.3 (d)(2), (e)(2), (f)(2)). */
  | 'rerack'
  /** Eight-ball: re-rack, and the player who broke illegally breaks again (WPA 3.3 (d)(3)). */
  | 'rerack-other';

/** The referee's verdict on one shot (or a decision), carried by the Game it produced. */
export interface Verdict {
  /** Index of the shot in the game, from 1. */
  shot: number;
  player: PlayerId;
  foul: boolean;
  /** A short code of the (first) foul, e.g. 'scratch', 'wrong-ball-first', 'no-rail'; null if none. */
  reason: string | null;
  /** Every foul found on the shot, first one first (same codes as reason). */
  fouls: string[];
  /** Points scored on this shot, per player (fouls give points to the opponent in snooker). */
  points: Record<PlayerId, number>;
  /** Object balls that went down on this shot and stay down. */
  potted: string[];
  /** Balls put back on the table by the rules (spotted). */
  spotted: string[];
  /** Whether the same player shoots again. */
  continues: boolean;
  /** Who is on turn after the shot. */
  next: PlayerId;
  /** What happened, in words. */
  message: string;
  /** Set when the shot ended the rack, frame or game: its winner. */
  rackWinner?: PlayerId;
  /** Set when the shot lost the rack: why (e.g. 'eight-early', 'eight-wrong-pocket'). */
  loss?: string;
}

/** Fields every game has. */
export interface GameBase {
  kind: GameKind;
  table: TableName;
  players: PlayerId[];
  /** Balls on the table (the cue ball included, also while in hand: at its current placement). */
  balls: Ball[];
  /** Who shoots next. */
  turn: PlayerId;
  ballInHand: BallInHand;
  /** Per player: racks won (pool), points of the frame (snooker), points (carom), pots (practice). */
  scores: Record<PlayerId, number>;
  winner: PlayerId | null;
  /** Shots played so far. */
  shots: number;
  /** State of the seeded generator (uint32): every random draw of the rules comes from here. */
  rng: number;
  /** Verdict of the last shot or decision; null before the first. */
  verdict: Verdict | null;
  /** Decisions the player on turn may take instead of shooting; empty most of the time. */
  choices: Choice[];
}

export interface NineBallGame extends GameBase {
  kind: 'nineball';
  /** Racks to win the match (WPA: a race); 1 by default. */
  raceTo: number;
  /** Who broke the current rack (the break alternates: WPA Regulation 15, standard format). */
  breaker: PlayerId;
  /** 'break' before the break shot; 'push-out' when the next shot may be a push-out; else 'play'. */
  phase: 'break' | 'push-out' | 'play';
  /** Consecutive standard fouls per player, for WPA 6.14/2.8 (three consecutive fouls). */
  fouls: Record<PlayerId, number>;
}

export type Group = 'solids' | 'stripes';

export interface EightBallGame extends GameBase {
  kind: 'eightball';
  raceTo: number;
  breaker: PlayerId;
  phase: 'break' | 'play';
  /** The group of each player once the table is no longer open (WPA 3.4); null while open. */
  groups: Record<PlayerId, Group> | null;
}

export type SnookerColour = 'yellow' | 'green' | 'brown' | 'blue' | 'pink' | 'black';

/**
 * The ball on for the striker: 'red' (any red); 'colour' (any colour, after a red or after the
 * last red, nominated or deemed); or one colour of the end sequence (WPBSA S3 R4).
 */
export type SnookerOn = 'red' | 'colour' | SnookerColour;

export interface SnookerGame extends GameBase {
  kind: 'snooker';
  on: SnookerOn;
  /** The striker may nominate a free ball (snookered after a foul: WPBSA S3 R12). */
  freeBall: boolean;
  /** Points of the current break, for the display. */
  break: number;
  /** The black has been re-spotted after a tie (WPBSA S3 R5(c)): next score or foul ends it. */
  respottedBlack: boolean;
  /** Who committed the foul that gave the current choices (snooker 'pass' makes them play again). */
  offender: PlayerId | null;
}

export interface ThreeCushionGame extends GameBase {
  kind: 'threecushion';
  raceTo: number;
  /** Innings per player (UMB: an inning is one visit to the table). */
  innings: Record<PlayerId, number>;
  /** Points of the current run. */
  run: number;
  /** Highest run per player. */
  highRun: Record<PlayerId, number>;
}

export type PracticeLayout = 'nineball' | 'eightball' | 'snooker' | 'threecushion' | 'empty';

/** One undoable step of practice: the state before it, and the shot if it was one. */
export interface PracticeStep {
  balls: Ball[];
  ballInHand: BallInHand;
  score: number;
  shot: Shot | null;
}

export interface PracticeGame extends GameBase {
  kind: 'practice';
  layout: PracticeLayout;
  /** Undo stack, oldest first. */
  history: PracticeStep[];
}

export type Game = NineBallGame | EightBallGame | SnookerGame | ThreeCushionGame | PracticeGame;

export interface NewGameOptions {
  /** Seed of the generator (uint32 or any string); 1 when omitted. */
  seed?: number | string;
  /** Pool: racks to win; three-cushion: points to win (15 by default). */
  raceTo?: number;
  /** Practice: the table (default: the layout's table, or pool-9ft). */
  table?: TableName;
  /** Practice: the starting layout (default: 'eightball' on pool, 'snooker', 'threecushion'). */
  layout?: PracticeLayout;
}
