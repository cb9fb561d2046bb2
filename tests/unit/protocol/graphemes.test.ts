// Defect 5 of issue 37: names (and chat) count and cut by user-perceived characters, so a name of
// emoji is neither cut mid-character nor refused as "control characters".
import { describe, expect, it } from 'vitest';
import { nameProblem, normalizeName } from '../../../server/players/names.ts';
import { cutGraphemes, graphemeCount, NAME_MAX, parseClientMessage, plainTextProblem } from '../../../shared/protocol/index.ts';

const FAMILY = '\u{1F468}\u200D\u{1F469}\u200D\u{1F467}\u200D\u{1F466}'; // man, woman, girl, boy joined
const SKIN_FAMILY = '\u{1F468}\u{1F3FB}\u200D\u{1F469}\u{1F3FB}\u200D\u{1F467}\u{1F3FB}\u200D\u{1F466}\u{1F3FB}';
const FLAG_FR = '\u{1F1EB}\u{1F1F7}';
const FLAG_SCOTLAND = '\u{1F3F4}\u{E0067}\u{E0062}\u{E0073}\u{E0063}\u{E0074}\u{E007F}';
const RAINBOW_FLAG = '\u{1F3F3}\uFE0F\u200D\u{1F308}';
const EMOJI = [FAMILY, SKIN_FAMILY, FLAG_FR, FLAG_SCOTLAND, RAINBOW_FLAG, '\u{1F600}', '\u{1F3B1}', '#\uFE0F\u20E3'];
const emojiName = (n: number) => Array.from({ length: n }, (_, i) => EMOJI[i % EMOJI.length]).join('');

const hello = (name: string) => parseClientMessage(JSON.stringify({ type: 'hello', id: 1, name }));
const rename = (name: string) => parseClientMessage(JSON.stringify({ type: 'rename', id: 1, name }));

describe('names of emoji', () => {
  it('a name of 32 emoji (families, flags, ZWJ and tag sequences) is accepted whole by the protocol and the server', () => {
    const name = emojiName(NAME_MAX);
    expect(name.length).toBeGreaterThan(NAME_MAX * 4); // far more than 32 UTF-16 code units
    expect(graphemeCount(name)).toBe(NAME_MAX);
    for (const r of [hello(name), rename(name)]) expect(r).toMatchObject({ ok: true, message: { name } });
    expect(normalizeName(name)).toBe(name);
    expect(nameProblem(normalizeName(name))).toBeUndefined();
  });

  it('33 are refused, saying at most 32 characters', () => {
    const name = emojiName(NAME_MAX + 1);
    expect(rename(name)).toMatchObject({ ok: false, message: expect.stringMatching(/name: must be at most 32 characters; this has 33/) });
    expect(nameProblem(normalizeName(name))).toMatch(/at most 32 characters .*this one has 33/);
    expect(nameProblem(normalizeName('x'.repeat(33)))).toMatch(/at most 32 characters/);
    expect(nameProblem(normalizeName('x'.repeat(32)))).toBeUndefined();
  });

  it('a cut keeps whole characters', () => {
    const name = emojiName(40);
    const cut = cutGraphemes(name, NAME_MAX);
    expect(cut).toBe(emojiName(NAME_MAX));
    expect(graphemeCount(cut)).toBe(NAME_MAX);
    expect(plainTextProblem(cut)).toBeUndefined();
  });

  it('still refuses control and invisible formatting characters, saying which', () => {
    for (const bad of ['Ann\u0000', 'line\nbreak', 'Ann\u2028Lee']) {
      expect(rename(bad)).toMatchObject({ ok: false, message: expect.stringMatching(/control characters/) });
    }
    // (The server's normal form turns line breaks into spaces; a NUL stays and is refused.)
    expect(nameProblem(normalizeName('Ann\u0000'))).toMatch(/control characters/);
    for (const bad of ['\u202Enimda', 'Ann\u200BLee', '\u2066Ann', '\u200Dx', 'a\uFEFFb']) {
      expect(plainTextProblem(bad), JSON.stringify(bad)).toMatch(/invisible formatting characters/);
      expect(nameProblem(normalizeName(`${bad}z`)), JSON.stringify(bad)).toMatch(/invisible formatting characters/);
    }
    // A joiner inside a character (as scripts and emoji use them) is fine.
    expect(plainTextProblem('\u0915\u094D\u200D\u0937')).toBeUndefined();
    // A lone surrogate (half an emoji) is never plain text.
    expect(plainTextProblem('\u{1F600}'.slice(0, 1))).toMatch(/control characters/);
  });
});
