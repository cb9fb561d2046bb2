// npm run figures — writes the cushion-impact figures (the paper's Figs. 9, 10 and 12, computed
// by the kernel) as SVG into docs/figures/.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { fig10, fig12, fig9 } from './figures-cushion.ts';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const dir = join(root, 'docs', 'figures');
mkdirSync(dir, { recursive: true });
for (const [name, svg] of [['cushion-fig9.svg', fig9()], ['cushion-fig10.svg', fig10()], ['cushion-fig12.svg', fig12()]] as const) {
  writeFileSync(join(dir, name), svg);
  console.log(`wrote docs/figures/${name}`);
}
