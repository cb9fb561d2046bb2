// Text as people count it: by user-perceived characters (grapheme clusters, Unicode UAX #29, from
// Intl.Segmenter), so that a flag or a family emoji counts as one and is never cut in half. Used
// by the schemas, the server's names and the client's inputs. (Not part of any simulation: the
// segmentation may differ between ICU versions only for characters newer than one of them.)

const SEGMENTER = new Intl.Segmenter('en', { granularity: 'grapheme' });

export function graphemes(text: string): string[] {
  return Array.from(SEGMENTER.segment(text), (s) => s.segment);
}

export function graphemeCount(text: string): number {
  let n = 0;
  for (const _ of SEGMENTER.segment(text)) n++;
  return n;
}

/** The first `max` user-perceived characters of `text`. */
export function cutGraphemes(text: string, max: number): string {
  return graphemes(text).slice(0, max).join('');
}

/** Control characters, line and paragraph separators, lone surrogates: never allowed. */
const CONTROL = /[\p{Cc}\p{Zl}\p{Zp}\p{Cs}]/u;
/** Format characters (bidi overrides, zero-width spaces...): allowed only as below. */
const FORMAT = /\p{Cf}/gu;
/** The joiners and emoji tag characters that emoji sequences (a family, a flag of a region) and some scripts need. */
const JOINING = /^[\u200C\u200D\u{E0020}-\u{E007F}]$/u;
/** Something a joiner can belong to: a letter, mark, digit, symbol or punctuation in the same character. */
const BASE = /[\p{L}\p{M}\p{N}\p{S}\p{P}]/u;

/**
 * Why `text` is not plain text, or undefined. Format characters pass only as joiners or emoji tags
 * inside a character with something visible in it (the zero-width joiner of a family emoji, the
 * tags of the flag of Scotland); any other (a bidi override, a zero-width space) is refused.
 */
export function plainTextProblem(text: string): string | undefined {
  if (CONTROL.test(text)) return 'must be plain text without control characters or line breaks';
  if (!FORMAT.test(text)) return undefined;
  FORMAT.lastIndex = 0;
  for (const g of graphemes(text)) {
    const formats = g.match(FORMAT);
    if (!formats) continue;
    if (!formats.every((c) => JOINING.test(c)) || !BASE.test(g.replace(FORMAT, ''))) {
      return 'must be plain text without invisible formatting characters (such as direction overrides or zero-width spaces)';
    }
  }
  return undefined;
}
