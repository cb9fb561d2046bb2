// Where a point of the table is on the page: the canvas's box, its CSS pixels per metre, and a
// table point in page coordinates (the table drawn lengthwise, as on a wide screen).
import type { Page } from 'playwright-core';
import { tableSpec } from '../../shared/physics/index.ts';
import { RAIL } from '../../client/table/draw.ts';

export interface TableOnScreen {
  readonly box: { x: number; y: number; width: number; height: number };
  /** CSS pixels per metre. */
  readonly scale: number;
  at(p: { x: number; y: number }): { x: number; y: number };
}

export async function tableOnScreen(page: Page, table: string): Promise<TableOnScreen> {
  const box = (await page.locator('canvas.table').boundingBox())!;
  const scale = box.width / (tableSpec(table).length + 2 * RAIL);
  return { box, scale, at: (p) => ({ x: box.x + box.width / 2 + p.x * scale, y: box.y + box.height / 2 - p.y * scale }) };
}
