// Aiming on a table view: the heading follows the pointer until a click holds it (or the arrow
// keys turn it), power and spin come from their controls or from pulling the cue back (a drag
// from the cue ball or from the stick, played on release), a ball in hand can be dragged inside
// its legal area, and the cue stick and the guidance the room allows are drawn: an aim line, the
// path to first contact with its ghost ball, or the cue ball's whole predicted path (simulated
// here with the same physics the server runs).
import { sampleOutcome, simulate, type Outcome } from '../../shared/physics/index.ts';
import { placementProblem, type Game } from '../../shared/rules/index.ts';
import { CANCEL_PX, DECIDE_PX, drawCue, fullPull, goesBack, MAX_SPEED, MIN_SPEED, onStick, powerFraction, powerWords, pullBack, pullToSpeed, speedToGap } from './cue.ts';
import { drawLegalArea } from './draw.ts';
import type { TableView } from './view.ts';

export { MAX_SPEED, MIN_SPEED };

export type Guidance = 'none' | 'contact' | 'path';

export interface AimState {
  heading: number;
  /** m/s. */
  speed: number;
  /** Tip offsets, fractions of R. */
  side: number;
  top: number;
  /** Where the ball in hand was dragged to, when it was. */
  cueBall?: { x: number; y: number };
}

export class Aim {
  readonly state: AimState = { heading: 0, speed: 2.5, side: 0, top: 0 };
  private game: Game | null = null;
  private cueId = 'cue';
  private active = false;
  private dragging = false;
  /** A press on a ball in hand whose drag has not yet shown whether it places the ball or pulls the cue. */
  private pressed: { x: number; y: number } | null = null;
  /** A click holds the aim: the mouse may then go to the controls without turning the cue. */
  private held = false;
  private preview: { key: string; outcome: Outcome | null } | null = null;
  private onChange: () => void = () => {};
  /** A stroke being pulled back: where the press was, the speed before it, the pull so far (m). */
  private stroke: { from: { x: number; y: number }; before: number; pull: number } | null = null;
  /** Plays the shot as aimed (a stroke released): the page's own shoot, as "Shoot" calls it. */
  onStroke: () => void = () => {};

  constructor(
    private readonly view: TableView,
    private guidance: Guidance,
  ) {
    const c = view.canvas;
    c.addEventListener('pointerdown', (e) => this.pointerDown(e));
    c.addEventListener('pointermove', (e) => this.pointerMove(e));
    c.addEventListener('pointerup', (e) => this.pointerUp(e));
    c.addEventListener('pointercancel', () => {
      // (A touch taken over by the browser, say for a scroll: nothing is played.)
      this.dragging = false;
      this.pressed = null;
      this.endStroke(false);
    });
    c.addEventListener('keydown', (e) => this.key(e));
  }

  /** The game to aim in, the ball struck, whether this page may aim now; `changed` redraws. */
  set(game: Game | null, cueId: string, active: boolean, guidance: Guidance, changed: () => void): void {
    const turnChanged = this.game?.shots !== game?.shots || this.game?.turn !== game?.turn || this.cueId !== cueId;
    this.game = game;
    this.cueId = cueId;
    this.active = active;
    this.guidance = guidance;
    this.onChange = changed;
    if (turnChanged) {
      delete this.state.cueBall;
      this.held = false;
      this.stroke = null;
      this.pressed = null;
    }
    this.preview = null;
  }

  /** Stops aiming (a shot is playing): no guidance, no input, until the next set(). */
  disable(): void {
    this.active = false;
    this.dragging = false;
    this.pressed = null;
    this.stroke = null;
  }


  /** The cue ball's place: dragged in hand, or where the game has it. */
  cuePosition(): { x: number; y: number } | null {
    if (this.state.cueBall) return this.state.cueBall;
    const b = this.game?.balls.find((x) => x.id === this.cueId);
    return b ? { x: b.x, y: b.y } : null;
  }

  /** The balls to draw, with the ball in hand where it was dragged. */
  balls(): { id: string; x: number; y: number }[] {
    const g = this.game;
    if (!g) return [];
    const p = this.state.cueBall;
    return g.balls.map((b) => (p && b.id === this.cueId ? { id: b.id, x: p.x, y: p.y } : b));
  }

  change(): void {
    this.preview = null;
    this.onChange();
  }

  private inHand(): boolean {
    return this.active && this.game !== null && this.game.ballInHand !== false;
  }

  private pointerDown(e: PointerEvent): void {
    if (!this.active) return;
    this.view.canvas.focus();
    const w = this.view.toWorld(e.clientX, e.clientY);
    const cue = this.cuePosition();
    const R = this.view.spec.ballRadius;
    const onBall = !!cue && Math.hypot(w.x - cue.x, w.y - cue.y) < R * 2;
    if (cue && onBall && this.inHand()) {
      this.pressed = w;
      this.view.canvas.setPointerCapture(e.pointerId);
      return;
    }
    // A press on the cue ball (not in hand) or on the stick behind it starts a stroke: pulling
    // back sets the power, and letting go plays it. It does not turn the aim.
    const reach = Math.max(R * 1.2, 12 / this.view.pixelsPerMetre);
    if (cue && (onBall || onStick(w, cue, this.state.heading, R, speedToGap(this.state.speed, fullPull(this.view.pixelsPerMetre)), reach))) {
      this.stroke = { from: w, before: this.state.speed, pull: 0 };
      this.held = true;
      this.view.canvas.setPointerCapture(e.pointerId);
      this.change();
      return;
    }
    this.held = true;
    this.aimAt(w);
  }

  private pointerUp(e: PointerEvent): void {
    this.dragging = false;
    this.pressed = null;
    if (!this.stroke) return;
    this.pointerMove(e);
    this.endStroke(true);
  }

  /** The speed of a pull (m), or null if it is too short to play; full power at 40 cm of table or 150 px, the longer. */
  private pullSpeed(pull: number): number | null {
    const ppm = this.view.pixelsPerMetre;
    return pullToSpeed(pull, CANCEL_PX / ppm, fullPull(ppm));
  }

  /** Ends a stroke: played if it was pulled back far enough (and `play`), else the power goes back. */
  private endStroke(play: boolean): void {
    const s = this.stroke;
    if (!s) return;
    this.stroke = null;
    const speed = this.pullSpeed(s.pull);
    this.state.speed = play && speed !== null ? speed : s.before;
    this.change();
    if (play && speed !== null) this.onStroke();
  }

  private pointerMove(e: PointerEvent): void {
    if (!this.active) return;
    const w = this.view.toWorld(e.clientX, e.clientY);
    const p = this.pressed;
    if (p) {
      // A ball in hand: a drag straight back from the aim pulls the cue; any other moves the ball.
      if (Math.hypot(w.x - p.x, w.y - p.y) * this.view.pixelsPerMetre < DECIDE_PX) return;
      this.pressed = null;
      if (goesBack(this.state.heading, p, w)) {
        this.stroke = { from: p, before: this.state.speed, pull: 0 };
        this.held = true;
      } else this.dragging = true;
    }
    if (this.stroke) {
      this.stroke.pull = pullBack(this.state.heading, this.stroke.from, w);
      this.state.speed = this.pullSpeed(this.stroke.pull) ?? this.stroke.before;
      this.change();
      return;
    }
    if (this.dragging) {
      this.placeAt(w);
      return;
    }
    // A mouse aims by hovering until a click holds the aim; pressing and dragging always aims.
    // Hovering over the cue ball does not (the way to it, to pull the cue, keeps the aim).
    const cue = this.cuePosition();
    const nearBall = !!cue && Math.hypot(w.x - cue.x, w.y - cue.y) < this.view.spec.ballRadius * 2.5;
    if (e.buttons !== 0 || (e.pointerType === 'mouse' && !this.held && !nearBall)) this.aimAt(w);
  }

  private aimAt(w: { x: number; y: number }): void {
    const cue = this.cuePosition();
    if (!cue || (w.x === cue.x && w.y === cue.y)) return;
    this.state.heading = Math.atan2(w.y - cue.y, w.x - cue.x);
    this.change();
  }

  /** Moves a ball in hand to `to` if that is a legal place: inside the area, on the bed, clear of the other balls. */
  private placeAt(to: { x: number; y: number }): void {
    const area = this.game?.ballInHand;
    if (!this.game || area === undefined || area === false) return;
    if (placementProblem(this.view.spec, this.game.balls, this.cueId, to, area) === null) {
      this.state.cueBall = to;
      this.change();
    }
  }

  private key(e: KeyboardEvent): void {
    if (!this.active || this.stroke) return;
    const fine = e.shiftKey ? 0.1 : 1;
    const move: Record<string, [number, number]> = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    if (e.altKey && move[e.key]) {
      // Alt + arrows move a ball in hand, 1 cm a press (1 mm with Shift), to legal places only.
      e.preventDefault();
      const cue = this.cuePosition();
      const [right, up] = move[e.key]!;
      const d = this.view.screenStep(right * 0.01 * fine, up * 0.01 * fine);
      if (cue) this.placeAt({ x: cue.x + d.x, y: cue.y + d.y });
      return;
    }
    if (e.key === 'ArrowLeft') this.state.heading += 0.008 * fine;
    else if (e.key === 'ArrowRight') this.state.heading -= 0.008 * fine;
    else if (e.key === 'ArrowUp') this.state.speed = Math.min(MAX_SPEED, this.state.speed + 0.25 * fine);
    else if (e.key === 'ArrowDown') this.state.speed = Math.max(MIN_SPEED, this.state.speed - 0.25 * fine);
    else return;
    e.preventDefault();
    this.change();
  }

  /** Draws the guidance, the cue stick and, while a stroke is pulled, its power (called from the view's overlay). */
  draw(ctx: CanvasRenderingContext2D): void {
    const cue = this.cuePosition();
    if (!this.active || !cue || !this.game) return;
    if (this.game.ballInHand !== false) drawLegalArea(ctx, this.view.spec, this.game.ballInHand);
    const R = this.view.spec.ballRadius;
    this.drawGuidance(ctx, cue, R);
    // While pulling, the tip follows the pull; else it stands off by the gap the power gives.
    const s = this.stroke;
    const cancelled = s !== null && this.pullSpeed(s.pull) === null;
    drawCue(ctx, cue, this.state.heading, R, s ? Math.min(s.pull, speedToGap(MAX_SPEED, fullPull(this.view.pixelsPerMetre))) : speedToGap(this.state.speed, fullPull(this.view.pixelsPerMetre)), this.state.side);
    if (s) this.drawMeter(ctx, cancelled ? null : this.state.speed);
  }

  /** The power meter while a stroke is pulled: a bar and its words on the top rail, between a corner and the middle pocket. */
  private drawMeter(ctx: CanvasRenderingContext2D, speed: number | null): void {
    const canvas = this.view.canvas;
    const cssW = parseFloat(canvas.style.width) || canvas.width;
    const dpr = canvas.width / cssW;
    ctx.save();
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const x = Math.round(cssW * 0.25 - 75);
    const y = 6;
    const w = 150;
    const f = speed === null ? 0 : powerFraction(speed);
    ctx.fillStyle = 'rgba(0,0,0,0.6)';
    ctx.fillRect(x - 4, y - 4, w + 8, 34);
    ctx.fillStyle = '#333';
    ctx.fillRect(x, y, w, 8);
    ctx.fillStyle = `hsl(${120 - 120 * f}, 75%, 50%)`;
    ctx.fillRect(x, y, w * f, 8);
    ctx.fillStyle = '#fff';
    ctx.font = '12px system-ui, sans-serif';
    ctx.textBaseline = 'top';
    ctx.fillText(speed === null ? 'Pull back; let go here to cancel' : `Power: ${powerWords(speed)}`, x, y + 12);
    ctx.restore();
  }

  private drawGuidance(ctx: CanvasRenderingContext2D, cue: { x: number; y: number }, R: number): void {
    ctx.strokeStyle = 'rgba(255,255,255,0.7)';
    ctx.lineWidth = 2 / this.view.pixelsPerMetre;
    if (this.guidance === 'none') {
      const len = 0.25 + 0.05 * this.state.speed;
      line(ctx, [cue, { x: cue.x + len * Math.cos(this.state.heading), y: cue.y + len * Math.sin(this.state.heading) }]);
      return;
    }
    const outcome = this.predict(cue);
    if (!outcome) return;
    const path = outcome.paths.find((p) => p.id === this.cueId);
    if (!path) return;
    const contact = outcome.events.find((e) => e.kind === 'ball' && e.balls.includes(this.cueId));
    const end = this.guidance === 'contact' && contact ? contact.t : outcome.duration;
    const points: { x: number; y: number }[] = [];
    for (let i = 0; i <= 60; i++) {
      const b = sampleOutcome(outcome, (end * i) / 60).find((x) => x.id === this.cueId);
      if (b) points.push(b);
    }
    line(ctx, points);
    const last = points.at(-1);
    if (last && contact) {
      ctx.beginPath();
      ctx.arc(last.x, last.y, R, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }

  /** The shot as aimed, simulated once per aim (the guidance's source). */
  private predict(cue: { x: number; y: number }): Outcome | null {
    const s = this.state;
    const key = `${s.heading}|${s.speed}|${s.side}|${s.top}|${cue.x}|${cue.y}`;
    if (this.preview?.key === key) return this.preview.outcome;
    let outcome: Outcome | null = null;
    try {
      outcome = simulate({ table: this.game!.table, balls: this.balls() }, { ball: this.cueId, heading: s.heading, speed: s.speed, side: s.side, top: s.top });
    } catch {
      outcome = null;
    }
    this.preview = { key, outcome };
    return outcome;
  }
}

function line(ctx: CanvasRenderingContext2D, pts: readonly { x: number; y: number }[]): void {
  if (pts.length < 2) return;
  ctx.beginPath();
  ctx.moveTo(pts[0]!.x, pts[0]!.y);
  for (const p of pts.slice(1)) ctx.lineTo(p.x, p.y);
  ctx.stroke();
}
