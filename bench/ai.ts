// npm run bench:ai — the computer opponent's strength and cost, seeded and bounded in time (see
// bench/ai/options.ts for --games, --racks, --frames, --only, --levels, --kinds, --budget). One
// module per kind of game under bench/ai/; prints markdown tables; asserts nothing.
import type { GameKind } from '../shared/rules/index.ts';
import { costTable } from './ai/cost.ts';
import { readOptions } from './ai/options.ts';
import type { Timing } from './ai/play.ts';
import { runOutTable, strengthTable } from './ai/pool.ts';
import { snookerTables } from './ai/snooker.ts';
import { caromTables } from './ai/carom.ts';

const o = readOptions(process.argv.slice(2));
const timings: Timing[] = [];
console.log(`# bench:ai (${new Date().toISOString().slice(0, 10)}, Node ${process.version}; options ${JSON.stringify(o)})`);
const t0 = performance.now();
if (o.only.includes('pool')) {
  for (const kind of o.kinds as GameKind[]) {
    runOutTable(kind, o, timings);
    strengthTable(kind, o, timings);
  }
}
if (o.only.includes('snooker')) snookerTables(o, timings);
if (o.only.includes('carom')) caromTables({ innings: o.innings, games: o.games, levels: o.levels, raceTo: 3, inningsCap: 25, budget: o.budget }, timings);
if (o.only.includes('cost')) costTable(timings);
console.log(`\n(${((performance.now() - t0) / 1000).toFixed(0)} s in all)`);
