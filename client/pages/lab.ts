// The physics lab: the paper's Figs. 9, 10 and 12 computed live by the kernel, a shot editor for
// the cushion constants and the incoming ball, a whole carom shot played with those constants,
// and the kernel's speed against its error beside the anchors' scheme. The state lives in the URL.
import { sampleOutcome, simulate, type Outcome } from '../../shared/physics/index.ts';
import { corpusCases, PAPER, paperState } from '../../shared/scenes/index.ts';
import { h } from '../dom.ts';
import { fig10, fig12, fig9, type Phases, type Rebound } from '../lab/figures.ts';
import { speedChartSvg, speedRows } from '../lab/speed.ts';
import { FIELDS, fromQuery, toQuery, value, withField, type Field, type LabState } from '../lab/state.ts';
import { TableView } from '../table/view.ts';

/** The preview's shot: the corpus's first three-cushion shot, on the carom table. */
const PREVIEW = corpusCases('carom')[0]!;

export function mountLab(root: HTMLElement): () => void {
  let state = fromQuery(location.search);
  const error = h('p', { role: 'alert', className: 'warn' });
  const timing = h('p', { role: 'status', 'aria-label': 'Redraw time' });
  const inputs = new Map<Field, HTMLInputElement>();
  const field = (f: (typeof FIELDS)[number]): HTMLElement => {
    const input = h('input', { type: 'number', min: f.min, max: f.max, step: f.step, name: f.key, value: value(state, f.key) });
    input.addEventListener('input', () => change(f.key, input));
    // Leaving a refused value (Enter, Tab, a click elsewhere) shows the value in use again.
    input.addEventListener('change', () => {
      if (input.getAttribute('aria-invalid') !== 'true') return;
      input.value = String(value(state, f.key));
      input.removeAttribute('aria-invalid');
      error.textContent = `${error.textContent?.replace(/; the figures use .*$/, '') ?? ''}; ${input.value} is still in use.`;
    });
    inputs.set(f.key, input);
    return h('label', { className: 'lab-field' }, f.label, ' ', input);
  };
  const constants = h('fieldset', {}, h('legend', {}, 'Constants'), ...FIELDS.slice(0, 6).map(field));
  const ball = h('fieldset', {}, h('legend', {}, 'Incoming ball (Fig. 12 and the rebound)'), ...FIELDS.slice(6).map(field));
  const reset = h('button', { type: 'button', onclick: () => apply({ params: PAPER, ball: state.ball }) }, "The paper's constants");
  const figure = (id: string, caption: string): { el: HTMLElement; body: HTMLElement } => {
    const body = h('div', { className: 'lab-plot' });
    return { el: h('figure', { id, 'aria-label': caption }, body, h('figcaption', {}, caption)), body };
  };
  const f9 = figure('fig9', 'Fig. 9: rebound speed and angle against incidence, topspins k = -1..2');
  const f10 = figure('fig10', 'Fig. 10: a rolling ball with sidespins k = -2..2');
  const f12 = figure('fig12', 'Fig. 12: slips and their directions against the impulse, with the impact\'s phases');
  const result = h('dl', { className: 'lab-result', 'aria-label': 'Rebound' });
  const phases = h('p', { 'aria-label': 'Phases' });
  const previewBox = h('div', { className: 'table-box' });
  const previewNote = h('p', {});
  const speedTable = h('tbody');
  const speedChart = h('div', { className: 'lab-plot' });
  root.append(
    h('section', { 'aria-label': 'Physics lab', className: 'lab' },
      h('h2', {}, 'Physics lab: the cushion impact'),
      h('p', {}, 'The model of Mathavan, Jackson and Parkin (2010), computed in this page by the same kernel the game uses. ',
        'Change a constant and every figure that depends on it is drawn again; the circles are the values the paper publishes (hover for the numbers).'),
      h('div', { className: 'lab-controls' }, constants, ball), h('p', {}, reset), error, timing,
      h('h3', {}, 'Rebound'), result, phases,
      f9.el, f10.el, f12.el,
      h('h3', {}, 'A whole shot with these constants'), previewNote, previewBox,
      h('h3', {}, 'Speed against error for this impact'),
      h('table', { 'aria-label': 'Speed against error' },
        h('thead', {}, h('tr', {}, h('th', {}, 'scheme'), h('th', {}, 'µs per impact'), h('th', {}, 'error / V0'))), speedTable),
      speedChart,
    ),
  );
  const view = new TableView(previewBox, PREVIEW.scene.table, 'Shot preview');
  let shown: LabState | undefined;
  let speedTimer: ReturnType<typeof setTimeout> | undefined;

  /** A value typed: taken, or refused (marked invalid, saying why and which value the figures use). */
  function change(key: Field, input: HTMLInputElement): void {
    const next = withField(state, key, input.valueAsNumber);
    if (typeof next === 'string') {
      input.setAttribute('aria-invalid', 'true');
      error.textContent = `${next}; the figures use ${value(state, key)} until a value is accepted.`;
      return;
    }
    input.removeAttribute('aria-invalid');
    apply(next);
  }

  function apply(next: LabState): void {
    error.textContent = '';
    const paramsChanged = !shown || JSON.stringify(shown.params) !== JSON.stringify(next.params);
    const ballChanged = !shown || JSON.stringify(shown.ball) !== JSON.stringify(next.ball);
    state = next;
    for (const [k, input] of inputs) {
      if (input.valueAsNumber !== value(state, k)) input.value = String(value(state, k));
      input.removeAttribute('aria-invalid');
    }
    history.replaceState(null, '', `/lab${toQuery(state)}`);
    const t0 = performance.now();
    if (paramsChanged) {
      f9.body.innerHTML = fig9(state.params);
      f10.body.innerHTML = fig10(state.params);
      preview();
    }
    if (paramsChanged || ballChanged) {
      const f = fig12(state.params, state.ball);
      f12.body.innerHTML = f.svg;
      showRebound(f.rebound, f.phases);
    }
    const ms = performance.now() - t0;
    root.dataset.redrawMs = ms.toFixed(1);
    timing.textContent = `Redrawn in ${ms.toFixed(1)} ms.`;
    shown = state;
    // The timings run after the figures are on screen.
    clearTimeout(speedTimer);
    speedTimer = setTimeout(showSpeed, 0);
  }

  function showRebound(r: Rebound, p: Phases): void {
    const row = (k: string, v: string): Node[] => [h('dt', {}, k), h('dd', {}, v)];
    result.replaceChildren(
      ...row('speed', `${r.speed.toFixed(4)} m/s`), ...row('angle', `${r.angle.toFixed(3)}° from the cushion`),
      ...row('spin ωx, ωy, ωz', `${r.wx.toFixed(2)}, ${r.wy.toFixed(2)}, ${r.wz.toFixed(2)} rad/s`),
    );
    const span = (s: { from: number; to: number; label: string }): string => `${s.label} ${s.from.toFixed(3)}-${s.to.toFixed(3)} N s`;
    phases.textContent = `Phases: ${p.halves.map(span).join(', ')}; contacts: ${p.contacts.map(span).join(', ')}.`;
  }

  function preview(): void {
    let out: Outcome;
    try {
      out = simulate(PREVIEW.scene, PREVIEW.shot, { cushion: state.params });
    } catch (e) {
      previewNote.textContent = `This shot cannot be played with these constants: ${(e as Error).message}`;
      return;
    }
    const n = 240;
    const tracks = out.paths.map(() => [] as { x: number; y: number }[]);
    for (let i = 0; i <= n; i++) sampleOutcome(out, (out.duration * i) / n).forEach((b, k) => tracks[k]!.push({ x: b.x, y: b.y }));
    view.setOverlay((ctx) => {
      ctx.lineWidth = 0.006;
      tracks.forEach((track, b) => {
        ctx.strokeStyle = ['#ffffff', '#ffd23f', '#e03131'][b] ?? '#333';
        ctx.beginPath();
        track.forEach((p, i) => (i === 0 ? ctx.moveTo(p.x, p.y) : ctx.lineTo(p.x, p.y)));
        ctx.stroke();
      });
    });
    view.draw(out.balls.map((b) => ({ id: b.id, x: b.x, y: b.y })));
    view.canvas.dataset.outcomeHash = out.hash;
    previewNote.textContent = `${PREVIEW.name}: ${out.events.filter((e) => e.kind === 'cushion').length} cushion impacts with the constants above, ${out.duration.toFixed(2)} s.`;
  }

  function showSpeed(): void {
    const s = paperState(state.ball.V0, state.ball.alpha, state.ball.kT, state.ball.kS, state.params.R);
    const rows = speedRows(s, state.params);
    speedTable.replaceChildren(...rows.map((r) => h('tr', {}, h('td', {}, r.name), h('td', {}, r.us.toFixed(2)), h('td', {}, r.error.toExponential(1)))));
    speedChart.innerHTML = speedChartSvg(rows);
  }

  apply(state);
  return () => {
    clearTimeout(speedTimer);
    view.destroy();
  };
}
