// A small helper to build DOM: h('button', { onclick }, 'Shoot'). Text is always text, never markup.
type Attrs = Record<string, string | number | boolean | ((e: Event) => void) | undefined>;
type Child = Node | string | number | null | undefined | false;

export function h<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Attrs = {}, ...children: Child[]): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === false) continue;
    if (typeof v === 'function') el.addEventListener(k.replace(/^on/, ''), v);
    else if (k === 'className') el.className = String(v);
    else if (v === true) el.setAttribute(k, '');
    else el.setAttribute(k, String(v));
  }
  for (const c of children) if (c !== null && c !== undefined && c !== false) el.append(typeof c === 'object' ? c : String(c));
  return el;
}

/** A link handled by the page's router. */
export function link(href: string, text: string): HTMLAnchorElement {
  return h('a', { href, 'data-link': true }, text);
}

export const KIND_NAMES: Readonly<Record<string, string>> = {
  nineball: 'Nine-ball',
  eightball: 'Eight-ball',
  snooker: 'Snooker',
  threecushion: 'Three-cushion',
};
