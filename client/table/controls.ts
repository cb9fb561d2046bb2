// The stroke's controls beside the table: power, the aim's heading, a spin picker (the tip's
// offset on the ball, kept inside the miscue limit) and the Shoot button; space shoots too.
import { h } from '../dom.ts';
import { MAX_SPEED, MIN_SPEED, type Aim } from './aim.ts';

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
  const power = h('input', { type: 'range', min: MIN_SPEED, max: MAX_SPEED, step: 0.05, value: aim.state.speed, 'aria-label': 'Power (m/s)' });
  // (Outputs are live regions by default; these change with every pointer move, so they are quiet.)
  const powerText = h('output', { 'aria-live': 'off' }, `${aim.state.speed.toFixed(2)} m/s`);
  power.addEventListener('input', () => {
    aim.state.speed = Number(power.value);
    powerText.textContent = `${aim.state.speed.toFixed(2)} m/s`;
    aim.change();
  });
  const spin = h('canvas', { width: 72, height: 72, className: 'spin', tabindex: 0, 'aria-label': 'Spin: click where the tip strikes the ball, or use the arrow keys', role: 'img' });
  const drawSpin = () => {
    const ctx = spin.getContext('2d');
    if (!ctx) return;
    ctx.clearRect(0, 0, 72, 72);
    ctx.fillStyle = '#f4f1e8';
    ctx.beginPath();
    ctx.arc(36, 36, 34, 0, 2 * Math.PI);
    ctx.fill();
    ctx.strokeStyle = '#c44';
    ctx.beginPath();
    ctx.arc(36, 36, 34 * MAX_OFFSET, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.fillStyle = '#2e5cb8';
    ctx.beginPath();
    ctx.arc(36 + 34 * aim.state.side, 36 - 34 * aim.state.top, 5, 0, 2 * Math.PI);
    ctx.fill();
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
  spin.addEventListener('pointerdown', (e) => {
    const r = spin.getBoundingClientRect();
    setSpin(((e.clientX - r.left) / r.width - 0.5) * 2, -((e.clientY - r.top) / r.height - 0.5) * 2);
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
  const element = h('div', { className: 'controls' }, h('label', {}, 'Power ', power, ' ', powerText), h('span', {}, 'Aim ', aimText), spin, shoot);
  showAim();
  drawSpin();
  return {
    element,
    shoot,
    enable(on) {
      shoot.disabled = !on;
      power.disabled = !on;
    },
    sync() {
      power.value = String(aim.state.speed);
      powerText.textContent = `${aim.state.speed.toFixed(2)} m/s`;
      showAim();
      drawSpin();
    },
  };
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
