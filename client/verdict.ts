// The referee's verdict in words: the rules' message with player names for player ids (only where
// the rules put a player, so ball numbers and points stay as they are) and each foul said plainly.
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

/**
 * Where the rules' messages name a player: at the start, and after these words. (Looked behind,
 * not matched: a word taken after ": " must not hide an id right after it, as in ": foul by 5".)
 */
const PLAYER = /(?<=foul on the break by |foul by |break by |point for |: |; | to |have |and |^)([\w-]+)(?=[\s:;,)]|$)/g;

export function inWords(message: string, names: (id: string) => string | undefined): string {
  const said = message
    .replace(/\(([a-z-]+(?:, [a-z-]+)*)\)/g, (m, codes: string) => (codes.split(', ').every((c) => FOULS[c]) ? `(${codes.split(', ').map((c) => FOULS[c]).join(', ')})` : m))
    .replace(PLAYER, (id: string) => names(id) ?? id)
    // Snooker's reds are told apart by the rules (red1, red2...), not by players.
    .replace(/\bred\d+\b/g, 'a red');
  return said.charAt(0).toUpperCase() + said.slice(1);
}
