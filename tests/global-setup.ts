// Builds the browser client once before the tests that serve or load it.
import { buildClient } from '../scripts/build-client.ts';

export default async function setup(): Promise<void> {
  await buildClient();
}
