// The referee's verdict in words, built from the Verdict's fields and the Game it produced (never
// by editing the rules' own message, whose ids and numbers can't be told apart).
import type { Choice, Game, PlayerId, Verdict } from '../shared/rules/index.ts';

const FOULS: Readonly<Record<string, string>> = {
  'no-contact': 'no ball hit',
  'no-rail': 'no rail after contact',
  scratch: 'the cue ball went in',
  'wrong-ball-first': 'wrong ball hit first',
  'illegal-break': 'not a legal break',
  'in-off': 'in-off',
  'pot-not-on': 'potted a ball not on',
  'free-ball-snooker': 'snookered behind the free ball',
  'kitchen-not-crossed': 'the cue ball did not leave the kitchen',
  'ball-off-table': 'a ball left the table',
  'break-red-first': 'the red not hit first on the opening',
};

/** The pockets as the screen shows them (+x to the right, +y up; shared/rules/pockets.ts). */
export const POCKET_NAMES: Readonly<Record<string, string>> = {
  BL: 'upper left corner', BR: 'lower left corner', ML: 'upper side', MR: 'lower side', TL: 'upper right corner', TR: 'lower right corner',
};

/** What made the verdict, when the page knows it (the verdict alone can't tell a pass from a miss). */
export interface VerdictHow {
  /** A stroke (the default), the shot clock running out, a concession, a claim, or a choice. */
  action?: 'shot' | 'clock' | 'concede' | 'claim' | 'decide';
  /** The stroke's declarations. */
  shot?: { readonly pushOut?: boolean; readonly calledPocket?: string; readonly ball?: string };
  choice?: Choice;
  /** The player reading it: said "You", with the verbs to match. */
  me?: PlayerId;
  /** The game before the stroke (tells a break, or the groups being taken). */
  before?: Game;
}

const COLOURS = ['yellow', 'green', 'brown', 'blue', 'pink', 'black'];

/** One ball as said: "the 9", "the pink", "a red". */
export function ballWord(id: string): string {
  return /^red\d*$/.test(id) ? 'a red' : `the ${id}`;
}

/** Balls as said: "the 3 and the 5", "2 reds and the black". */
export function ballsWords(ids: readonly string[]): string {
  const reds = ids.filter((id) => /^red\d*$/.test(id)).length;
  const words = [...(reds === 0 ? [] : [reds === 1 ? 'a red' : `${reds} reds`]), ...ids.filter((id) => !/^red\d*$/.test(id)).map(ballWord)];
  if (words.length === 0) return 'nothing';
  return words.length === 1 ? words[0]! : `${words.slice(0, -1).join(', ')} and ${words[words.length - 1]}`;
}

function foulWords(v: Verdict): string {
  return v.fouls.map((c) => FOULS[c] ?? c.replace(/-/g, ' ')).join(', ');
}

function capital(s: string): string {
  return s.charAt(0).toUpperCase() + s.slice(1);
}

/**
 * The verdict as one sentence. `names` gives a player's name; `how` says what made the verdict
 * (a stroke by default) and who reads it.
 */
export function verdictSentence(game: Game, v: Verdict, names: (id: PlayerId) => string, how: VerdictHow = {}): string {
  const you = (id: PlayerId) => how.me !== undefined && id === how.me;
  const who = (id: PlayerId) => (you(id) ? 'you' : names(id));
  /** A verb for a subject: "Ann pockets", "you pocket". */
  const does = (id: PlayerId, third: string, base: string) => `${who(id)} ${you(id) ? base : third}`;
  const has = (id: PlayerId) => does(id, 'has', 'have');
  const p = v.player;
  const other = game.players.find((x) => x !== p) ?? v.next;
  const action = how.action ?? 'shot';
  let s: string;

  if (action === 'concede' || action === 'claim' || v.loss === 'concession') {
    const winner = v.rackWinner ?? other;
    s = action === 'claim'
      ? `${does(winner, 'claims', 'claim')} the game: ${does(p, 'has', 'have')} left; ${does(winner, 'wins', 'win')}`
      : `${does(p, 'concedes', 'concede')}; ${does(winner, 'wins', 'win')}`;
    return end(s);
  }
  if (action === 'decide') {
    s = how.choice === 'pass' || how.choice === undefined
      ? `${does(p, 'passes', 'pass')}: ${who(v.next)} to play`
      : `the balls are racked again; ${does(v.next, 'breaks', 'break')}`;
    return end(s);
  }
  // A run-out is judged as a stroke that meets nothing: say the clock, not "no ball hit".
  const clock = action === 'clock';
  const fouls = foulWords(v);
  const foulBy = clock ? `${who(p)} ran out of time` : `foul by ${who(p)} (${fouls})`;
  const verb = (id: PlayerId, third: string, base: string) => (you(id) ? base : third);
  /** "the rack", or "the game" when it ended the match. */
  const what = (id: PlayerId, unit: string) => (game.winner === id ? 'the game' : `the ${unit}`);

  switch (game.kind) {
    case 'nineball':
    case 'eightball': {
      const pool = game;
      const called = how.shot?.calledPocket;
      const pocket = called === undefined ? undefined : POCKET_NAMES[called] ?? called;
      if (v.loss === 'three-fouls') s = `${clock ? `${who(p)} ran out of time, a third foul in a row,` : `${does(p, 'fouls', 'foul')} (${fouls}) for the third time in a row`} and ${verb(p, 'loses', 'lose')} ${what(other, 'rack')}`;
      else if (v.loss?.startsWith('eight-')) {
        const why = v.loss === 'eight-early' ? 'before clearing the group' : v.loss === 'eight-with-foul' ? `with a foul (${fouls})` : pocket === undefined ? 'without calling a pocket' : `in another pocket than the called ${pocket}`;
        s = `${does(p, 'pockets', 'pocket')} the 8 ${why} and ${verb(p, 'loses', 'lose')} ${what(other, 'rack')}`;
      } else if (v.rackWinner === p && !v.foul) {
        const ball = pool.kind === 'eightball' ? '8' : '9';
        s = `${does(p, 'pockets', 'pocket')} the ${ball}${pool.kind === 'eightball' && pocket ? ` in the called ${pocket}` : ''} and ${verb(p, 'wins', 'win')} ${what(p, 'rack')}`;
      } else if (v.fouls.includes('illegal-break')) {
        s = `illegal break by ${who(p)}: ${who(other)} may play on, re-rack and break, or have ${who(p)} break again`;
      } else if (v.foul) {
        const inHand = pool.ballInHand === 'kitchen' ? ' in the kitchen' : '';
        s = `${foulBy}: ${has(v.next)} ball in hand${inHand}`;
        if (v.spotted.length) s += `; ${ballsWords(v.spotted)} ${v.spotted.length === 1 ? 'is' : 'are'} spotted`;
        if (pool.kind === 'nineball' && pool.fouls[p] === 2) s += `; ${does(p, 'is', 'are')} on two fouls`;
        if (pool.choices.includes('rerack')) s += ', or may re-rack';
        return end(s);
      } else if (pool.kind === 'nineball' && (how.shot?.pushOut || (pool.choices.includes('pass') && !v.continues))) {
        s = `${does(p, 'pushes out', 'push out')}${v.potted.length ? ` (potted ${ballsWords(v.potted)})` : ''}; ${who(other)} may shoot or pass the shot back`;
      } else if (v.spotted.includes('8')) {
        s = `${does(p, 'pockets', 'pocket')} the 8 on the break: it is spotted${v.continues ? `; ${does(p, 'continues', 'continue')}` : ''}, or may re-break`;
      } else if (v.potted.length > 0) {
        // Eight-ball: the groups are taken by the first legal pot after the break (open table before).
        const before = how.before;
        const takes = pool.kind === 'eightball' && pool.groups && before?.kind === 'eightball' && before.groups === null && before.phase === 'play' ? pool.groups[p] : undefined;
        const open = pool.kind === 'eightball' && pool.groups === null;
        s = `${does(p, 'pockets', 'pocket')} ${ballsWords(v.potted)}` + (
          takes ? ` and ${verb(p, 'takes', 'take')} the ${takes}` :
          open ? `; the table is open` + (v.continues ? `; ${does(p, 'continues', 'continue')}` : `; ${who(v.next)} to play`) :
          v.continues ? ` and ${verb(p, 'continues', 'continue')}` :
          ` (not ${you(p) ? 'your' : 'their'} group); ${who(v.next)} to play`);
      } else {
        const broke = (pool.kind === 'nineball' && pool.phase === 'push-out') || (how.before !== undefined && 'phase' in how.before && how.before.phase === 'break');
        s = broke ? `legal break by ${who(p)}, nothing down; ${who(v.next)} to play` : `${does(p, 'misses', 'miss')}; ${who(v.next)} to play`;
      }
      return end(s);
    }
    case 'snooker': {
      const g = game;
      const penalty = v.points[other] ?? 0;
      if (v.foul) {
        s = `${foulBy}: ${penalty} points to ${who(other)}`;
        if (g.freeBall) s += '; free ball';
      } else {
        const scored = v.points[p] ?? 0;
        const balls = [...new Set([...v.potted, ...v.spotted.filter((id) => COLOURS.includes(id))])];
        s = scored > 0 ? `${does(p, 'pots', 'pot')} ${ballsWords(balls)} for ${scored} (break ${g.break})` : `${does(p, 'scores', 'score')} nothing; ${who(v.next)} to play`;
      }
      if (v.rackWinner !== undefined) {
        const scores = g.players.map((id) => g.scores[id] ?? 0);
        s += `; ${does(v.rackWinner, 'wins', 'win')} the frame ${Math.max(...scores)}-${Math.min(...scores)}`;
      } else if (g.respottedBlack && v.spotted.includes('black') && g.ballInHand === 'D' && g.choices.includes('pass')) {
        s += `; scores level: the black is re-spotted, ${does(v.next, 'wins', 'win')} the lot and plays from hand or passes`;
      } else if (g.winner === null) {
        s += `; ball on: ${g.on === 'red' ? 'a red' : g.on === 'colour' ? 'a colour' : `the ${g.on}`}`;
      }
      return end(s);
    }
    case 'threecushion': {
      const g = game;
      if ((v.points[p] ?? 0) > 0) {
        s = `point for ${who(p)} (run ${g.run})`;
        if (g.winner === p) s += `; ${does(p, 'reaches', 'reach')} ${g.raceTo} and ${verb(p, 'wins', 'win')}`;
      } else s = clock ? `${who(p)} ran out of time; ${who(v.next)} to play` : `no point for ${who(p)}${v.foul ? ` (foul: ${fouls})` : ''}; ${who(v.next)} to play`;
      return end(s);
    }
    case 'practice': {
      s = v.potted.length ? `${does(p, 'pockets', 'pocket')} ${ballsWords(v.potted)}` : `${who(p)} potted nothing`;
      if (v.fouls.includes('scratch')) s += game.ballInHand ? '; the cue ball went down: it is in hand anywhere' : '; the cue ball went down';
      return end(s);
    }
  }
}

function end(s: string): string {
  const t = capital(s);
  return /[.!?]$/.test(t) ? t : `${t}.`;
}
