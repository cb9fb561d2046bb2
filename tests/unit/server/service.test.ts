// The game service in-process over a real SQLite file, with a clock the test moves: the cases of
// tests/contract/service.cases.ts (the same run over PostgreSQL in tests/integration). The same
// service runs behind the WebSocket binding in tests/integration.
import { serviceCases } from '../../contract/service.cases.ts';
import { openHarness } from '../../support/service-harness.ts';

serviceCases(openHarness);
