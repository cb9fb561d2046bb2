// Types of the kept bundle: the same simulate(scene, shot) as today's, returning an Outcome.
import type { Outcome, Scene, Shot } from '../../shared/physics/index.ts';

export function simulate(scene: Scene, shot: Shot): Outcome;
