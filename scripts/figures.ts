// npm run figures — writes the cushion-impact figures (the paper's Figs. 9, 10 and 12, computed
// by the kernel with the paper's constants, as the lab page draws them) as SVG into docs/figures/.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { fig10, fig12, fig9, FIG12_BALL } from '../client/lab/figures.ts';
import { PAPER } from '../shared/scenes/index.ts';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const dir = join(root, 'docs', 'figures');
mkdirSync(dir, { recursive: true });
const figures = [['cushion-fig9.svg', fig9(PAPER)], ['cushion-fig10.svg', fig10(PAPER)], ['cushion-fig12.svg', fig12(PAPER, FIG12_BALL).svg]] as const;
for (const [name, svg] of figures) {
  writeFileSync(join(dir, name), svg);
  console.log(`wrote docs/figures/${name}`);
}
