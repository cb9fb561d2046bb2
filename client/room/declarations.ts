// The rules' declarations and choices for the stroke about to be played (a push-out, eight-ball's
// called pocket, snooker's nomination, a pass or re-rack). Its inputs are the player's: never
// made for them, kept through updates of the room, and cleared for each new stroke.
import { legalTargets, POCKETS, type Game, type Shot } from '../../shared/rules/index.ts';
import { h } from '../dom.ts';
import { POCKET_NAMES } from '../verdict.ts';

type Choice = Game['choices'][number];

export class Declarations {
  readonly element = h('div', { className: 'declarations' });
  private readonly pushOut = h('input', { type: 'checkbox', 'aria-label': 'Push-out' });
  // No call or nomination is made until the player makes one: a default would be a silent choice.
  private readonly called = h(
    'select',
    { 'aria-label': 'Called pocket' },
    h('option', { value: '' }, 'choose a pocket'),
    ...POCKETS.map((p) => h('option', { value: p }, POCKET_NAMES[p] ?? p)),
  );
  private readonly nominated = h('select', { 'aria-label': 'Nominated ball' });
  /** The shot count the declarations were made for: a new stroke starts with none. */
  private declaredAt = -1;

  /** Shows what `game` asks of the player (nothing when it is not their turn). */
  update(g: Game | null, myTurn: boolean, decide: (choice: Choice) => void): void {
    const { pushOut, called, nominated } = this;
    this.element.replaceChildren();
    if (!g || !myTurn) return;
    if (g.shots !== this.declaredAt) {
      this.declaredAt = g.shots;
      called.value = '';
      nominated.value = '';
      pushOut.checked = false;
    }
    if (g.kind === 'nineball' && g.phase === 'push-out') this.element.append(h('label', {}, pushOut, ' Push-out'));
    if (callsThe8(g)) this.element.append(h('label', {}, 'Called pocket for the 8 ', called));
    if (g.kind === 'snooker' && (g.on === 'colour' || g.freeBall)) {
      const options = g.freeBall ? g.balls.filter((b) => b.id !== 'cue').map((b) => b.id) : ['yellow', 'green', 'brown', 'blue', 'pink', 'black'];
      const kept = nominated.value;
      const onTable = options.filter((o) => g.balls.some((b) => b.id === o));
      nominated.replaceChildren(
        h('option', { value: '' }, g.freeBall ? 'no free ball' : 'the colour hit first'),
        ...onTable.map((o) => h('option', { value: o }, o)),
      );
      nominated.value = onTable.includes(kept) ? kept : '';
      this.element.append(h('label', {}, 'Nominate ', nominated));
    }
    for (const choice of g.choices) {
      const label = choice === 'pass' ? 'Pass (opponent plays)' : choice === 'rerack' ? 'Re-rack and break' : 'Re-rack, they break again';
      this.element.append(h('button', { type: 'button', onclick: () => decide(choice) }, label));
    }
  }

  /** A shot at the 8 waits for its pocket to be called. */
  missingCall(g: Game): boolean {
    return callsThe8(g) && !this.called.value;
  }

  /** The shot with this turn's declarations. */
  declare(g: Game, shot: Omit<Shot, 'player'>): Omit<Shot, 'player'> {
    const s = { ...shot };
    if (g.kind === 'nineball' && g.phase === 'push-out' && this.pushOut.checked) s.pushOut = true;
    if (callsThe8(g) && this.called.value) s.calledPocket = this.called.value as Shot['calledPocket'];
    if (g.kind === 'snooker' && (g.on === 'colour' || g.freeBall) && this.nominated.value) s.nominated = this.nominated.value;
    return s;
  }
}

const callsThe8 = (g: Game) => g.kind === 'eightball' && g.groups !== null && legalTargets(g).includes('8');
