// The one error the referees throw for an illegal action. The Game given in is never changed.

export type RuleErrorCode =
  | 'game-over'
  | 'wrong-player'
  | 'bad-player'
  | 'wrong-ball'
  | 'bad-shot'
  | 'bad-declaration'
  | 'bad-placement'
  | 'not-in-hand'
  | 'bad-choice'
  | 'bad-outcome'
  | 'bad-options'
  | 'nothing-to-undo';

export class RuleError extends Error {
  readonly code: RuleErrorCode;

  constructor(code: RuleErrorCode, message: string) {
    super(message);
    this.name = 'RuleError';
    this.code = code;
  }
}
