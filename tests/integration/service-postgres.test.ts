// The game service's cases (tests/contract/service.cases.ts) over PostgreSQL: a real server
// started by the test (tests/support/postgres.ts), a fresh database for each case. Skips without
// PostgreSQL's binaries, unless BAIZE_REQUIRE_POSTGRES=1.
import { afterAll, beforeAll, describe } from 'vitest';
import { serviceCases } from '../contract/service.cases.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';
import { openHarness } from '../support/service-harness.ts';

describe.skipIf(!postgresAvailable())('the game service on PostgreSQL', () => {
  let server: PostgresServer;
  let made = 0;
  beforeAll(async () => {
    server = await startPostgres();
  }, 60_000);
  afterAll(async () => {
    await server?.stop();
  });
  serviceCases(async (options) => openHarness({ ...options, databaseUrl: await server.database(`service_${++made}`) }));
});
