// Pocket ids shared by the referees and (later) the physics.
//
// Naming: stand at the bottom end of the table (x = -length/2: the head end of a pool table, whose
// kitchen is there; the baulk end of a snooker table) and look along +x towards the top (foot) end.
// The first letter is the end: B = bottom corner pockets (x = -length/2), M = middle (side) pockets
// (x = 0), T = top corner pockets (x = +length/2). The second letter is the side: L = left, which
// is +y (x forward, z up, right-handed), R = right, which is -y.
//
//            -x (bottom / head / baulk)                    +x (top / foot)
//   +y  BL ---------------------- ML ---------------------- TL
//       |                                                   |
//   -y  BR ---------------------- MR ---------------------- TR

export const POCKETS = ['BL', 'BR', 'ML', 'MR', 'TL', 'TR'] as const;
export type PocketId = (typeof POCKETS)[number];

/** Where each pocket lies, as signs: x in {-1, 0, 1} times length/2, y in {-1, 1} times width/2. */
export const POCKET_SIDES: Readonly<Record<PocketId, { readonly x: -1 | 0 | 1; readonly y: -1 | 1 }>> = {
  BL: { x: -1, y: 1 },
  BR: { x: -1, y: -1 },
  ML: { x: 0, y: 1 },
  MR: { x: 0, y: -1 },
  TL: { x: 1, y: 1 },
  TR: { x: 1, y: -1 },
};

export function isPocketId(value: unknown): value is PocketId {
  return typeof value === 'string' && (POCKETS as readonly string[]).includes(value);
}
