// Small pieces of English shared by the pages.

/** "1 game", "2 games", "0 games": a count with its noun in agreement. */
export function count(n: number, one: string, many = `${one}s`): string {
  return `${n} ${n === 1 ? one : many}`;
}
