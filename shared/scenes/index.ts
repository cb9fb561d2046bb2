// Scenes defined once: the golden corpus and the helpers that build scenes and aim shots.
export { CORPUS, corpusCases } from './corpus.ts';
export type { CorpusCase, CorpusTag } from './corpus.ts';
export { aim, ghost, shot, onRail, frozenLine, generator, randomBalls } from './build.ts';
export { randomShots } from './random-shots.ts';
export type { Point } from './build.ts';
export { PAPER, paperState, PUBLISHED } from './cushion-paper.ts';
export type { PublishedRebound } from './cushion-paper.ts';
