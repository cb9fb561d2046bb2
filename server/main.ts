// `npm start`: reads the environment, starts the server, stops cleanly on SIGINT and SIGTERM.
import { readConfig } from './config.ts';
import { startServer } from './app.ts';

async function main(): Promise<void> {
  const config = readConfig();
  const server = await startServer(config);
  console.log(
    server.migrationsApplied.length > 0
      ? `database ${config.dbPath}: applied ${server.migrationsApplied.join(', ')}; schema ${server.schema}`
      : `database ${config.dbPath}: schema ${server.schema}, up to date`,
  );
  const stop = (signal: string) => {
    console.log(`${signal} received, stopping`);
    server.close().then(
      () => {
        console.log('stopped');
        process.exit(0);
      },
      (err: unknown) => {
        console.error(`error while stopping: ${(err as Error).message}`);
        process.exit(1);
      },
    );
  };
  process.once('SIGINT', () => stop('SIGINT'));
  process.once('SIGTERM', () => stop('SIGTERM'));
  // Last: whoever waits for this line may signal at once, and the handlers are in place.
  console.log(`listening on ${server.url}`);
}

main().catch((err: unknown) => {
  console.error(`baize: ${err instanceof Error ? err.message : String(err)}`);
  process.exit(1);
});
