// The stroke's controls beside the table: a power meter (a range input that reads in words), the
// aim's heading, the spin picker (where the tip strikes the drawn cue ball, kept inside the
// miscue limit) and the Shoot button; space shoots too, and so does a stroke pulled on the table.
import { h } from '../dom.ts';
import { MAX_SPEED, MIN_SPEED, type Aim } from './aim.ts';
import { powerFraction, powerWords } from './cue.ts';

/** The largest tip offset offered: inside the miscue limit of 0.5 R. */
const MAX_OFFSET = 0.45;

export interface Controls {
  readonly element: HTMLElement;
  readonly shoot: HTMLButtonElement;
  /** Enables the controls when it is this page's turn. */
  enable(on: boolean): void;
  /** Reflects the aim's power and spin (after keys changed them). */
  sync(): void;
}

export function strokeControls(aim: Aim, onShoot: () => void): Controls {
  aim.onStroke = onShoot;
  const power = h('input', { type: 'range', min: MIN_SPEED, max: MAX_SPEED, step: 0.05, value: aim.state.speed, 'aria-label': 'Power' });
  // (Outputs are live regions by default; these change with every pointer move, so they are quiet.)
  const powerText = h('output', { 'aria-live': 'off', className: 'power-words' });
  const showPower = () => {
    const v = aim.state.speed;
    power.value = String(v);
    power.setAttribute('aria-valuetext', `${powerWords(v)} (${v.toFixed(2)} m/s)`);
    powerText.textContent = `${powerWords(v)} · ${v.toFixed(2)} m/s`;
    // The range's filled part is the meter: green when soft to red at full power.
    power.style.accentColor = `hsl(${Math.round(120 - 120 * powerFraction(v))}, 70%, 45%)`;
  };
  power.addEventListener('input', () => {
    aim.state.speed = Number(power.value);
    showPower();
    aim.change();
  });
  // The tip's place on the cue ball, as the player sees it from behind: a 2D slider.
  const spinHint = h('span', { className: 'note spin-words', id: `spin-words-${++ids}` });
  const spin = h('canvas', {
    width: 144,
    height: 144,
    className: 'spin',
    tabindex: 0,
    role: 'slider',
    'aria-label': 'Spin',
    'aria-valuemin': 0,
    'aria-valuemax': 100,
    'aria-describedby': spinHint.id,
    title: 'Click where the tip strikes the cue ball, or use the arrow keys',
  });
  const drawSpin = () => {
    const ctx = spin.getContext('2d');
    if (!ctx) return;
    // Drawn at twice its CSS size, for sharp edges on high-DPI screens.
    const c = 72;
    const r = 66;
    ctx.clearRect(0, 0, 144, 144);
    const shade = ctx.createRadialGradient(c - r * 0.35, c - r * 0.4, r * 0.1, c, c, r);
    shade.addColorStop(0, '#ffffff');
    shade.addColorStop(0.6, '#ece8dc');
    shade.addColorStop(1, '#b9b3a2');
    ctx.fillStyle = shade;
    ctx.beginPath();
    ctx.arc(c, c, r, 0, 2 * Math.PI);
    ctx.fill();
    // The miscue limit, and the cross through the centre.
    ctx.strokeStyle = 'rgba(180,50,40,0.8)';
    ctx.lineWidth = 2;
    ctx.setLineDash([6, 5]);
    ctx.beginPath();
    ctx.arc(c, c, r * MAX_OFFSET, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.strokeStyle = 'rgba(0,0,0,0.18)';
    ctx.beginPath();
    ctx.moveTo(c - r, c);
    ctx.lineTo(c + r, c);
    ctx.moveTo(c, c - r);
    ctx.lineTo(c, c + r);
    ctx.stroke();
    // The tip: a chalked disc about the size of a real tip on the ball.
    const tx = c + r * aim.state.side;
    const ty = c - r * aim.state.top;
    ctx.fillStyle = '#3d7fd9';
    ctx.strokeStyle = '#123';
    ctx.beginPath();
    ctx.arc(tx, ty, r * 0.22, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
    const words = spinWords(aim.state.side, aim.state.top);
    spinHint.textContent = words;
    spin.setAttribute('aria-valuetext', words);
    spin.setAttribute('aria-valuenow', String(Math.round((Math.hypot(aim.state.side, aim.state.top) / MAX_OFFSET) * 100)));
  };
  /** Puts the tip at (side, top), pulled back inside the miscue limit. */
  const setSpin = (side: number, top: number) => {
    const d = Math.hypot(side, top);
    if (d > MAX_OFFSET) {
      side *= MAX_OFFSET / d;
      top *= MAX_OFFSET / d;
    }
    aim.state.side = Math.round(side * 100) / 100;
    aim.state.top = Math.round(top * 100) / 100;
    drawSpin();
    aim.change();
  };
  const spinAt = (e: PointerEvent) => {
    const r = spin.getBoundingClientRect();
    setSpin(((e.clientX - r.left) / r.width - 0.5) * 2, -((e.clientY - r.top) / r.height - 0.5) * 2);
  };
  // A press puts the tip there; dragging moves it.
  spin.addEventListener('pointerdown', (e) => {
    spin.setPointerCapture(e.pointerId);
    spinAt(e);
  });
  spin.addEventListener('pointermove', (e) => {
    if (e.buttons !== 0) spinAt(e);
  });
  spin.addEventListener('keydown', (e) => {
    const step: Record<string, [number, number]> = { ArrowLeft: [-0.05, 0], ArrowRight: [0.05, 0], ArrowUp: [0, 0.05], ArrowDown: [0, -0.05] };
    const d = step[e.key];
    if (!d) return;
    e.preventDefault();
    setSpin(aim.state.side + d[0], aim.state.top + d[1]);
  });
  const shoot = h('button', { type: 'button', className: 'shoot', onclick: () => onShoot() }, 'Shoot');
  // The heading in degrees from the table's long axis, counter-clockwise (as the protocol has it).
  const aimText = h('output', { 'aria-label': 'Aim', 'aria-live': 'off' });
  const showAim = () => {
    const deg = (aim.state.heading * 180) / Math.PI;
    // Hundredths: a fine key step (Shift) turns the cue by about 0.05°.
    aimText.textContent = `${(((deg % 360) + 360) % 360).toFixed(2)}°`;
  };
  const element = h(
    'div',
    { className: 'controls' },
    h('label', { className: 'power' }, 'Power ', power, ' ', powerText),
    h('span', {}, 'Aim ', aimText),
    h('span', { className: 'spin-box' }, h('span', { 'aria-hidden': 'true' }, 'Spin'), spin, spinHint),
    shoot,
  );
  showAim();
  showPower();
  drawSpin();
  return {
    element,
    shoot,
    enable(on) {
      shoot.disabled = !on;
      power.disabled = !on;
    },
    sync() {
      showPower();
      showAim();
      drawSpin();
    },
  };
}

let ids = 0;

/** Where the tip strikes, in words: "Centre", "Top 20%, left 10%" (of the ball's radius). */
export function spinWords(side: number, top: number): string {
  const pct = (v: number) => `${Math.round(Math.abs(v) * 100)}%`;
  const parts: string[] = [];
  if (Math.abs(top) >= 0.005) parts.push(`${top > 0 ? 'top (follow)' : 'bottom (draw)'} ${pct(top)}`);
  if (Math.abs(side) >= 0.005) parts.push(`${side > 0 ? 'right' : 'left'} side ${pct(side)}`);
  const text = parts.length === 0 ? 'centre ball' : parts.join(', ');
  return text[0]!.toUpperCase() + text.slice(1);
}

/** Space shoots when the table or the page has the focus (not while typing). */
export function spaceShoots(onShoot: () => void): () => void {
  const handler = (e: KeyboardEvent) => {
    const t = e.target as HTMLElement | null;
    if (e.key !== ' ' || (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT' || t.tagName === 'BUTTON'))) return;
    e.preventDefault();
    onShoot();
  };
  document.addEventListener('keydown', handler);
  return () => document.removeEventListener('keydown', handler);
}
