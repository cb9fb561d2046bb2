// /help: the four games as this server's referee (shared/rules) judges them, the controls, and
// what the room's settings and the ratings mean. Static text: no state, no server.
import { h, link } from '../dom.ts';

type Child = Node | string;
const p = (...c: Child[]) => h('p', {}, ...c);
const ul = (...items: (string | Child[])[]) => h('ul', {}, ...items.map((i) => h('li', {}, ...(typeof i === 'string' ? [i] : i))));
const dl = (...rows: [string, string][]) => h('dl', { className: 'help-terms' }, ...rows.flatMap(([t, d]) => [h('dt', {}, t), h('dd', {}, d)]));
const section = (title: string, ...body: Node[]) => h('section', { 'aria-label': title }, h('h3', {}, title), ...body);

export function mountHelp(root: HTMLElement): () => void {
  root.append(
    h(
      'article',
      { className: 'help', 'aria-label': 'Help' },
      h('h2', {}, 'How to play'),
      p('The server is the referee: it plays every shot with the same physics your browser shows and judges it by the rules below. ',
        'Open a table in the ', link('/', 'lobby'), ', send the invite link to a friend or wait for someone to join, or ', link('/practice', 'practise alone'), '.'),
      section(
        'Nine-ball',
        p('Nine balls, numbered 1 to 9, racked in a diamond. You must always hit the lowest-numbered ball on the table first. Any ball you pot after a legal hit counts, and you keep shooting as long as you pot. Whoever pots the 9 legally wins the rack, even on the break.'),
        ul(
          'The break is played from behind the head string (the kitchen); it must pot a ball or send at least four balls to a cushion.',
          'After a legal hit a ball must go into a pocket, or some ball (the cue ball too) must touch a cushion.',
          'Fouls: the wrong ball first, no ball hit, no cushion after contact, the cue ball potted. After a foul the opponent has ball in hand anywhere on the table.',
          'A 9 potted on a foul or on a push-out comes back to its spot.',
          'Three fouls in a row by the same player lose the rack.',
          'On the shot right after the break the player may declare a push-out (see below).',
        ),
      ),
      section(
        'Eight-ball',
        p('Fifteen balls: solids 1 to 7, stripes 9 to 15 and the black 8. The table is open until someone pots a ball legally: that player takes its group (solids or stripes) and the other player the other one. Pot all of your group, then the 8 into the pocket you call.'),
        ul(
          'The break must pot a ball or send at least four balls to a cushion; otherwise the opponent may play on from there, break again, or have the breaker break again. An 8 potted on the break comes back to its spot, or the breaker (after a scratch, the opponent) may choose a new break.',
          'A cue ball potted on the break gives the opponent ball in hand in the kitchen; that first stroke must leave the kitchen before it meets a ball.',
          'While the table is open you may hit any ball first except the 8; after that, a ball of your own group first.',
          'Before a shot at the 8 you call its pocket (the table page offers the pockets by where they are on your screen). Only the 8 is called.',
          'You lose the rack if you pot the 8 before your group is cleared, together with your last ball, on a foul, or into a pocket you did not call.',
          'Other fouls (wrong ball first, no ball hit, no cushion after contact, the cue ball potted) give the opponent ball in hand anywhere.',
        ),
      ),
      section(
        'Snooker',
        p('Fifteen reds and six colours. While reds are on the table you play a red (1 point, and any number of reds may drop on one stroke), then a colour of your choice (yellow 2, green 3, brown 4, blue 5, pink 6, black 7), then a red again. A potted colour comes back to its spot as long as reds remain, and once more for the colour played after the last red. Then the colours are taken in order, yellow to black, and stay down.'),
        ul(
          'Name the colour you are playing after a red, or let the referee take the colour you hit first.',
          'Fouls: no ball hit, the wrong ball first, a ball not on potted, the cue ball potted (an in-off). A foul gives the opponent the value of the ball on or of the highest ball involved, at least 4.',
          'After a foul the opponent may play from where the balls lie or pass the turn back to the player who fouled.',
          'If a foul leaves you snookered (no straight line to both edges of a ball on), you get a free ball: any ball may be played as if it were the ball on.',
          'The frame ends when the black is potted or fouled at the end; a tie puts the black back on its spot for one more shot. A match is a race of frames, the break alternating.',
        ),
      ),
      section(
        'Three-cushion',
        p('A carom game on a table without pockets, with three balls: your cue ball (white or yellow), the other player\'s and the red. You score a point when your cue ball hits both other balls and, before it meets the second of them, has touched cushions at least three times (cushions before the first ball count too).'),
        ul(
          'You keep shooting while you score; a miss ends your inning and the other player plays their own cue ball.',
          'The opening shot must hit the red first.',
          'The first to the race (15 points unless the table says otherwise) wins. Innings, runs and the high run are counted.',
        ),
      ),
      section(
        'Controls',
        ul(
          [h('strong', {}, 'Aim: '), 'move the mouse over the table; the cue follows it. A click holds the aim for the turn, so that you can move to the buttons without turning the cue; click or drag on the table to aim again. On a touch screen, touch and drag to aim.'],
          [h('strong', {}, 'Shoot by dragging: '), 'press on the cue ball and drag back, away from where you aim; the length of the drag is the power (shown by the cue and a meter). Let go to play the shot.'],
          [h('strong', {}, 'Power and spin: '), 'the power slider sets the speed of the cue ball; the spin disc shows where the tip strikes the ball (above the centre for follow, below for draw, left or right for side), kept inside the limit where the cue would miscue.'],
          [h('strong', {}, '"Shoot" '), 'or the Space bar plays the shot as aimed.'],
          [h('strong', {}, 'Keyboard: '), 'with the table focused, Left and Right turn the cue, Up and Down change the power (hold Shift for fine steps); the arrow keys move the tip on the spin disc when it has the focus.'],
          [h('strong', {}, 'Ball in hand: '), 'drag the cue ball to where you want it, or use Alt and the arrow keys (1 cm a press, 1 mm with Shift). Only the legal area is accepted: the whole table, the kitchen, or the D in snooker; a refused spot says why.'],
          [h('strong', {}, '"Sound" '), 'switches the table\'s sounds on or off; the page remembers your choice.'],
          [h('strong', {}, 'On a phone: '), 'held upright, the table turns so that its length runs down the screen and the balls are bigger; on its side, the controls sit beside the table.'],
          [h('strong', {}, '"Fast forward" '), '(or the F key) while a shot is rolling plays it faster or skips to where the balls stop. It changes only what you watch: the shot and its result are the same for everyone.'],
        ),
      ),
      section(
        'Terms',
        dl(
          ['Guidance', 'Chosen when a table is opened; it limits what the players\' pages may show before a shot. "Aim to first contact": the cue ball\'s path to the first ball it meets, with a ghost ball where it touches. "Full cue-ball path": the cue ball\'s whole predicted path, cushions included. "No guidance": a short aim line from the cue ball, nothing more.'],
          ['Push-out', 'Nine-ball only: on the shot right after a legal break, the player may declare a push-out. The cue ball need not hit the lowest ball and no cushion is needed; a 9 that drops comes back to its spot. Then the opponent chooses to shoot from there or to pass the shot back.'],
          ['Ball in hand', 'The player may place the cue ball before shooting. In pool it follows every foul and may go anywhere on the table, except after a scratch on an eight-ball break: then behind the head string (the kitchen). In snooker it starts each frame and follows a cue ball that went into a pocket, and goes in the D. The page draws the legal area while you place the ball.'],
          ['Shot clock', 'If a table has one, the player on turn has that many seconds, from the moment the balls stop. When it runs out the referee counts a stroke that hits nothing: ball in hand to the opponent in pool, a foul of 4 or more in snooker, the end of the inning in three-cushion. The clock stops while neither player is connected.'],
          ['Rating', 'Each game has its own rating, computed by Glicko-2: everyone starts at 1500. A win over a stronger player gains more than a win over a weaker one.'],
          ['RD', 'Rating deviation: how unsure the rating still is. It starts at 350 and shrinks as you play. A rating with an RD of 110 or more is provisional (shown with a "?"): it is on your own page but not on the leaderboard.'],
          ['Rated match', 'A match counts for the ratings only when it was a real game: each player took at least 3 shots and it lasted at least a minute. At most 3 results a day between the same two players are rated. Once a board has 10 players, beating a provisional player does not move an established rating.'],
        ),
        p('See the ', link('/leaderboard', 'leaderboard'), ' for the ranked players and records.'),
      ),
    ),
  );
  return () => {};
}
