// The scoreboard: what is left to play for, read from the Game (pure numbers, then plain DOM).
import { legalTargets, SNOOKER_VALUES, type Game, type PlayerId, type SnookerColour } from '../../shared/rules/index.ts';
import { h } from '../dom.ts';

export interface ScoreLine {
  readonly label: string;
  readonly value: string;
}

const isRed = (id: string) => /^red\d*$/.test(id);

/** Snooker: the most points still on the table (each red with a black, then the colours; a colour due after a red counts 7). */
export function snookerPointsLeft(game: Game): number {
  if (game.kind !== 'snooker') return 0;
  const reds = game.balls.filter((b) => isRed(b.id)).length;
  const colours = game.balls.reduce((sum, b) => sum + (SNOOKER_VALUES[b.id as SnookerColour] ?? 0), 0);
  return reds * 8 + colours + (game.on === 'colour' ? 7 : 0);
}

/** Three-cushion: points per inning, to three decimals (0 before the first inning). */
export function caromAverage(points: number, innings: number): string {
  return (innings > 0 ? points / innings : 0).toFixed(3);
}

/** The lines of the scoreboard for the game in play. */
export function scoreLines(game: Game, name: (id: PlayerId) => string): ScoreLine[] {
  switch (game.kind) {
    case 'snooker': {
      const on = game.on === 'red' ? 'a red' : game.on === 'colour' ? 'a colour' : `the ${game.on}`;
      return [
        { label: 'Ball on', value: game.freeBall ? `${on} (free ball)` : on },
        { label: 'Reds left', value: String(game.balls.filter((b) => isRed(b.id)).length) },
        { label: 'Points left', value: String(snookerPointsLeft(game)) },
        { label: 'Break', value: String(game.break) },
      ];
    }
    case 'nineball': {
      const left = game.balls.filter((b) => b.id !== 'cue').length;
      return [
        { label: 'Ball on', value: legalTargets(game).map((id) => `the ${id}`).join(', ') || 'none' },
        { label: 'Balls left', value: String(left) },
      ];
    }
    case 'eightball': {
      const left = (lo: number, hi: number) => game.balls.filter((b) => Number(b.id) >= lo && Number(b.id) <= hi).length;
      const groups = game.groups;
      if (!groups) return [{ label: 'Groups', value: 'open table' }, { label: 'Balls left', value: `solids ${left(1, 7)}, stripes ${left(9, 15)}` }];
      return game.players.map((p) => ({
        label: name(p),
        value: `${groups[p]}, ${groups[p] === 'solids' ? left(1, 7) : left(9, 15)} left`,
      }));
    }
    case 'threecushion':
      return [
        ...game.players.map((p) => ({
          label: name(p),
          value: `${game.scores[p] ?? 0} in ${game.innings[p] ?? 0} innings, average ${caromAverage(game.scores[p] ?? 0, game.innings[p] ?? 0)}, high run ${game.highRun[p] ?? 0}`,
        })),
        { label: 'Run', value: String(game.run) },
      ];
    case 'practice':
      return [];
  }
}

/** The scoreboard as DOM (a description list named "Scoreboard"). */
export function renderScoreboard(game: Game | null, name: (id: PlayerId) => string): HTMLElement {
  const lines = game ? scoreLines(game, name) : [];
  return h('dl', { className: 'scoreboard', 'aria-label': 'Scoreboard', hidden: lines.length === 0 }, ...lines.flatMap((l) => [h('dt', {}, l.label), h('dd', {}, l.value)]));
}
