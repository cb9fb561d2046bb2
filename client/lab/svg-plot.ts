// A small hand-written SVG line-chart writer (no dependency): panels with axes, ticks, units,
// a legend, polylines, marked points with their numbers on hover and shaded spans, laid out side
// by side in one figure. Used by the lab page and by `npm run figures` (docs/figures).

export interface Series {
  readonly name: string;
  readonly points: readonly (readonly [number, number])[];
  readonly color: string;
  readonly dash?: string;
}

export interface Panel {
  readonly title: string;
  readonly xLabel: string;
  readonly yLabel: string;
  readonly series: readonly Series[];
  /** Optional fixed ranges; otherwise taken from the data with nice rounding. */
  readonly x?: readonly [number, number];
  readonly y?: readonly [number, number];
  /**
   * Where the legend goes: below the panel, outside the plot so that it never hides a curve
   * (default), or in a corner inside the plot: top/bottom, left/right.
   */
  readonly legend?: 'below' | 'tl' | 'tr' | 'bl' | 'br';
  /** Points drawn as circles, their label shown on hover (an SVG title). */
  readonly marks?: readonly Mark[];
  /** Shaded spans of x, labelled at their top. */
  readonly spans?: readonly Span[];
}

export interface Mark {
  readonly x: number;
  readonly y: number;
  readonly color: string;
  readonly label: string;
}

export interface Span {
  readonly from: number;
  readonly to: number;
  readonly label: string;
  readonly color: string;
}

export const PALETTE = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b'] as const;

const PANEL_W = 440;
const PANEL_H = 320;
const MARGIN = { left: 62, right: 16, top: 34, bottom: 50 };
/** A legend below the panel: entries in columns, rows this tall. */
const LEGEND_COLUMNS = 3;
const LEGEND_ROW = 16;

/** Height a panel's legend adds below it. */
function legendHeight(p: Panel): number {
  return (p.legend ?? 'below') === 'below' && p.series.length > 0 ? Math.ceil(p.series.length / LEGEND_COLUMNS) * LEGEND_ROW + 6 : 0;
}

function esc(s: string): string {
  return s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

/** About `count` round tick values covering [lo, hi]. */
export function niceTicks(lo: number, hi: number, count = 6): number[] {
  const span = hi - lo || Math.abs(hi) || 1;
  const raw = span / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => span / s <= count) ?? 10 * mag;
  const out: number[] = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

function range(values: number[]): [number, number] {
  let lo = Math.min(...values);
  let hi = Math.max(...values);
  if (lo === hi) {
    lo -= 1;
    hi += 1;
  }
  const t = niceTicks(lo, hi);
  const step = t.length > 1 ? t[1]! - t[0]! : 1;
  return [Math.floor(lo / step) * step, Math.ceil(hi / step) * step];
}

function fmt(v: number): string {
  return Number.parseFloat(v.toPrecision(6)).toString();
}

function panelSvg(p: Panel, ox: number, oy: number): string {
  const xs = [...p.series.flatMap((s) => s.points.map((q) => q[0])), ...(p.marks ?? []).map((m) => m.x)];
  const ys = [...p.series.flatMap((s) => s.points.map((q) => q[1])), ...(p.marks ?? []).map((m) => m.y)];
  const [x0, x1] = p.x ?? range(xs);
  const [y0, y1] = p.y ?? range(ys);
  const w = PANEL_W - MARGIN.left - MARGIN.right;
  const h = PANEL_H - MARGIN.top - MARGIN.bottom;
  const X = (v: number): number => MARGIN.left + ((v - x0) / (x1 - x0)) * w;
  const Y = (v: number): number => MARGIN.top + h - ((v - y0) / (y1 - y0)) * h;
  const out: string[] = [`<g transform="translate(${ox},${oy})">`];
  out.push(`<text x="${MARGIN.left + w / 2}" y="20" text-anchor="middle" font-size="14" font-weight="bold">${esc(p.title)}</text>`);
  for (const sp of p.spans ?? []) {
    const a = Math.max(X(sp.from), MARGIN.left);
    const b = Math.min(X(sp.to), MARGIN.left + w);
    if (!(b > a)) continue;
    out.push(`<rect data-span="${esc(sp.label)}" x="${a.toFixed(1)}" y="${MARGIN.top}" width="${(b - a).toFixed(1)}" height="${h}" fill="${sp.color}" fill-opacity="0.12"><title>${esc(sp.label)}</title></rect>`);
    out.push(`<text x="${((a + b) / 2).toFixed(1)}" y="${MARGIN.top + h - 6}" text-anchor="middle" font-size="9" fill="#555">${esc(sp.label)}</text>`);
  }
  out.push(`<rect x="${MARGIN.left}" y="${MARGIN.top}" width="${w}" height="${h}" fill="none" stroke="#333"/>`);
  for (const t of niceTicks(x0, x1)) {
    const x = X(t).toFixed(1);
    out.push(`<line x1="${x}" y1="${MARGIN.top}" x2="${x}" y2="${MARGIN.top + h}" stroke="#ddd"/>`);
    out.push(`<line x1="${x}" y1="${MARGIN.top + h}" x2="${x}" y2="${MARGIN.top + h + 5}" stroke="#333"/>`);
    out.push(`<text x="${x}" y="${MARGIN.top + h + 18}" text-anchor="middle" font-size="11">${fmt(t)}</text>`);
  }
  for (const t of niceTicks(y0, y1)) {
    const y = Y(t).toFixed(1);
    out.push(`<line x1="${MARGIN.left}" y1="${y}" x2="${MARGIN.left + w}" y2="${y}" stroke="#ddd"/>`);
    out.push(`<line x1="${MARGIN.left - 5}" y1="${y}" x2="${MARGIN.left}" y2="${y}" stroke="#333"/>`);
    out.push(`<text x="${MARGIN.left - 8}" y="${Number(y) + 4}" text-anchor="end" font-size="11">${fmt(t)}</text>`);
  }
  out.push(`<text x="${MARGIN.left + w / 2}" y="${PANEL_H - 10}" text-anchor="middle" font-size="12">${esc(p.xLabel)}</text>`);
  out.push(`<text transform="translate(16,${MARGIN.top + h / 2}) rotate(-90)" text-anchor="middle" font-size="12">${esc(p.yLabel)}</text>`);
  out.push(`<clipPath id="clip${ox}_${oy}"><rect x="${MARGIN.left}" y="${MARGIN.top}" width="${w}" height="${h}"/></clipPath>`);
  for (const s of p.series) {
    const pts = s.points.map(([a, b]) => `${X(a).toFixed(2)},${Y(b).toFixed(2)}`).join(' ');
    const dash = s.dash ? ` stroke-dasharray="${s.dash}"` : '';
    out.push(`<polyline data-series="${esc(s.name)}" clip-path="url(#clip${ox}_${oy})" fill="none" stroke="${s.color}" stroke-width="1.8"${dash} points="${pts}"/>`);
  }
  for (const m of p.marks ?? []) {
    out.push(`<circle data-mark="${esc(m.label)}" cx="${X(m.x).toFixed(2)}" cy="${Y(m.y).toFixed(2)}" r="4.5" fill="white" stroke="${m.color}" stroke-width="2"><title>${esc(m.label)}</title></circle>`);
  }
  // The legend: below the panel (under the x axis's label), or in a corner inside the plot.
  const corner = p.legend ?? 'below';
  const colW = w / LEGEND_COLUMNS;
  p.series.forEach((s, i) => {
    const below = corner === 'below';
    const lx = below ? MARGIN.left + (i % LEGEND_COLUMNS) * colW + 6 : corner[1] === 'r' ? MARGIN.left + w - 150 : MARGIN.left + 10;
    const ly = below ? PANEL_H + 12 + Math.floor(i / LEGEND_COLUMNS) * LEGEND_ROW : corner[0] === 't' ? MARGIN.top + 14 + i * 16 : MARGIN.top + h - 8 - (p.series.length - 1 - i) * 16;
    const dash = s.dash ? ` stroke-dasharray="${s.dash}"` : '';
    out.push(`<rect data-legend="${esc(s.name)}" x="${lx - 6}" y="${ly - 11}" width="${below ? colW : 150}" height="16" fill="white" fill-opacity="0.8"/>`);
    out.push(`<line x1="${lx}" y1="${ly - 4}" x2="${lx + 22}" y2="${ly - 4}" stroke="${s.color}" stroke-width="2"${dash}/>`);
    out.push(`<text x="${lx + 28}" y="${ly}" font-size="11">${esc(s.name)}</text>`);
  });
  out.push('</g>');
  return out.join('\n');
}

/** A figure: a title, a caption line and panels side by side. */
export function figureSvg(title: string, caption: string, panels: readonly Panel[]): string {
  const width = PANEL_W * panels.length;
  const height = PANEL_H + 56 + Math.max(0, ...panels.map(legendHeight));
  const body = panels.map((p, i) => panelSvg(p, i * PANEL_W, 40)).join('\n');
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="Helvetica, Arial, sans-serif">`,
    `<rect width="100%" height="100%" fill="white"/>`,
    `<text x="${width / 2}" y="20" text-anchor="middle" font-size="16" font-weight="bold">${esc(title)}</text>`,
    `<text x="${width / 2}" y="36" text-anchor="middle" font-size="11" fill="#555">${esc(caption)}</text>`,
    body,
    `</svg>`,
    '',
  ].join('\n');
}
