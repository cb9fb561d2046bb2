// npm run bench:sim — the table simulation's speed against a fixed-step yardstick, and what each
// accuracy setting costs and saves. Prints markdown tables; asserts nothing.
import { simulate, type Outcome, type SimOptions } from '../shared/physics/index.ts';
import { corpusCases, randomShots, type CorpusCase, type CorpusTag } from '../shared/scenes/index.ts';
import { simulate as simulateBefore28 } from './baseline/simulate-before-28.js';
import { simulateFixedStep } from './fixed-step.ts';
import { fmt, median, medianMs } from './timing.ts';

const GROUPS: readonly [string, CorpusTag][] = [
  ['9-ball breaks', 'nineball-break'],
  ['snooker breaks', 'snooker-break'],
  ['three-ball carom shots', 'carom'],
  ['single-ball shots', 'single'],
];

function runnable(cases: readonly CorpusCase[], options?: SimOptions): CorpusCase[] {
  return cases.filter((c) => {
    try {
      simulate(c.scene, c.shot, options);
      return true;
    } catch (err) {
      console.error(`skipped "${c.name}": ${(err as Error).message.slice(0, 160)}`);
      return false;
    }
  });
}

console.log(`# bench:sim (${new Date().toISOString().slice(0, 10)}, Node ${process.version})\n`);
console.log('## Event-driven simulation against a fixed-step integrator (1/512 s, explicit Euler, same physics)\n');
console.log('| scenes | n | median ms/shot | events/shot | simulated s/shot | ms per simulated s | fixed-step ms per simulated s | ratio |');
console.log('|---|---|---|---|---|---|---|---|');
for (const [label, tag] of GROUPS) {
  const cases = runnable(corpusCases(tag));
  if (cases.length === 0) continue;
  const ms: number[] = [];
  const events: number[] = [];
  const durations: number[] = [];
  const perSecond: number[] = [];
  const fixedPerSecond: number[] = [];
  for (const c of cases) {
    let out: Outcome | undefined;
    const t = medianMs(() => {
      out = simulate(c.scene, c.shot);
    });
    ms.push(t);
    events.push(out!.events.length);
    durations.push(out!.duration);
    perSecond.push(t / out!.duration);
    let fixedDuration = 1;
    const tf = medianMs(
      () => {
        fixedDuration = simulateFixedStep(c.scene, c.shot).duration;
      },
      5,
      20,
    );
    fixedPerSecond.push(tf / fixedDuration);
  }
  const ratio = median(fixedPerSecond) / median(perSecond);
  console.log(`| ${label} | ${cases.length} | ${fmt(median(ms))} | ${fmt(median(events))} | ${fmt(median(durations))} | ${fmt(median(perSecond))} | ${fmt(median(fixedPerSecond))} | ${fmt(ratio)}x cheaper |`);
}

console.log('\n## Against the simulation before issue 28, side by side\n');
console.log('The same scenes and table constants through today\'s simulate and the bundle of 1fe2acb (bench/baseline), timed alternately in this process. "time vs before" is the median over the scenes of today\'s time over the old one\'s; "total" the ratio of the summed times.\n');
console.log('| scenes | n | median ms/shot today | before | events/shot today | before | time vs before (median) | total |');
console.log('|---|---|---|---|---|---|---|---|');
const SIDE_BY_SIDE: readonly [string, readonly CorpusCase[]][] = [
  ...GROUPS.map(([label, tag]): [string, readonly CorpusCase[]] => [label, corpusCases(tag)]),
  ['random pool shots', randomShots('pool-9ft', 40)],
  ['random snooker shots', randomShots('snooker-12ft', 40)],
  ['random carom shots', randomShots('carom-match', 40)],
];
for (const [label, group] of SIDE_BY_SIDE) {
  const cases = runnable(group).filter((c) => {
    try {
      simulateBefore28(c.scene, c.shot);
      return true;
    } catch {
      return false;
    }
  });
  if (cases.length === 0) continue;
  const now: number[] = [];
  const before: number[] = [];
  const ratios: number[] = [];
  const eventsNow: number[] = [];
  const eventsBefore: number[] = [];
  for (const c of cases) {
    const b = medianMs(() => simulateBefore28(c.scene, c.shot), 5, 10);
    const a = medianMs(() => simulate(c.scene, c.shot), 5, 10);
    now.push(a);
    before.push(b);
    ratios.push(a / b);
    eventsNow.push(simulate(c.scene, c.shot).events.length);
    eventsBefore.push(simulateBefore28(c.scene, c.shot).events.length);
  }
  const sum = (xs: number[]): number => xs.reduce((x, y) => x + y, 0);
  console.log(`| ${label} | ${cases.length} | ${fmt(median(now))} | ${fmt(median(before))} | ${fmt(median(eventsNow))} | ${fmt(median(eventsBefore))} | ${fmt(median(ratios))}x | ${fmt(sum(now) / sum(before))}x |`);
}

console.log('\n## Accuracy settings: time saved and final-position error against the tightest setting\n');
const SETTINGS: readonly [string, SimOptions][] = [
  ['tightest: root 1e-15 s, cushion accurate', { rootTolerance: 1e-15, cushionTolerance: 'accurate' }],
  ['default: root 1e-12 s, cushion accurate', {}],
  ['root 1e-9 s', { rootTolerance: 1e-9 }],
  ['root 1e-6 s', { rootTolerance: 1e-6 }],
  ['cushion balanced', { cushionTolerance: 'balanced' }],
  ['cushion fast', { cushionTolerance: 'fast' }],
  ['root 1e-6 s, cushion fast', { rootTolerance: 1e-6, cushionTolerance: 'fast' }],
];
const all = runnable(corpusCases().filter((c) => !c.tags.includes('random')), SETTINGS[0]![1]);
const reference = all.map((c) => simulate(c.scene, c.shot, SETTINGS[0]![1]));
console.log(`${all.length} corpus cases (breaks, banks, spin, pockets, hard cases). Breaks are chaotic: a tiny change early can move balls far, so the median matters more than the maximum.\n`);
console.log('| setting | total ms (all cases) | time vs tightest | median position error (m) | max position error (m) | cases whose pockets differ |');
console.log('|---|---|---|---|---|---|');
let base = 0;
for (const [label, options] of SETTINGS) {
  const total = medianMs(() => {
    for (const c of all) simulate(c.scene, c.shot, options);
  }, 5, 50);
  if (base === 0) base = total;
  const errs: number[] = [];
  let pocketsDiffer = 0;
  all.forEach((c, i) => {
    const o = simulate(c.scene, c.shot, options);
    let worst = 0;
    o.balls.forEach((b, j) => {
      const r = reference[i]!.balls[j]!;
      worst = Math.max(worst, Math.hypot(b.x - r.x, b.y - r.y));
      if (b.pocket !== r.pocket) pocketsDiffer += 0; // counted per case below
    });
    if (o.balls.some((b, j) => b.pocket !== reference[i]!.balls[j]!.pocket)) pocketsDiffer++;
    errs.push(worst);
  });
  console.log(`| ${label} | ${fmt(total)} | ${fmt((100 * total) / base)}% | ${fmt(median(errs))} | ${fmt(Math.max(...errs))} | ${pocketsDiffer} |`);
}
