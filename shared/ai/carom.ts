// Three-cushion: see carom/index.ts (search over paths round the table by simulation).
export { chooseCaromShot } from './carom/index.ts';
