// The errors a command can meet, each turned into the protocol's { code, message }.
import { MiscueError, SimulationInputError } from '../../shared/physics/index.ts';
import type { ErrorCode } from '../../shared/protocol/index.ts';
import { RuleError } from '../../shared/rules/index.ts';

export class ServiceError extends Error {
  constructor(
    readonly code: ErrorCode,
    message: string,
  ) {
    super(message);
    this.name = 'ServiceError';
  }
}

/** The code and message of any error a command threw; `internal` for a bug, whose details stay in the log. */
export function describeError(err: unknown): { code: ErrorCode; message: string; internal: boolean } {
  if (err instanceof ServiceError) return { code: err.code, message: err.message, internal: false };
  if (err instanceof RuleError) return { code: err.code === 'nothing-to-undo' ? 'bad-choice' : err.code, message: err.message, internal: false };
  if (err instanceof MiscueError) return { code: 'miscue', message: err.message, internal: false };
  if (err instanceof SimulationInputError) return { code: 'bad-shot', message: err.message, internal: false };
  return { code: 'internal', message: 'the server could not carry out the request', internal: true };
}
