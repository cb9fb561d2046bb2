// A table on a canvas fitted to its container and sharp on high-DPI screens: the world (metres,
// y up, origin at the table's centre) mapped to device pixels, redrawn on demand.
import { tableSpec, type TableSpec } from '../../shared/physics/index.ts';
import { drawBall, drawShadow, drawTable, RAIL, type DrawnBall } from './draw.ts';
import { Orientations } from './orientation.ts';

export type Overlay = (ctx: CanvasRenderingContext2D, view: TableView) => void;

/** A phone held upright: the table turns a quarter, its length down the screen, so balls are bigger. */
const UPRIGHT_PHONE = '(orientation: portrait) and (max-width: 600px)';
/** A phone on its side: the room puts its controls beside the table (style.css), which may fill the height. */
const SIDEWAYS_PHONE = '(orientation: landscape) and (max-height: 520px)';

export class TableView {
  readonly canvas: HTMLCanvasElement;
  readonly spec: TableSpec;
  private scale = 1;
  /** Drawn turned a quarter (+x up the screen, +y to the left): see UPRIGHT_PHONE. */
  private turned = false;
  private balls: readonly DrawnBall[] = [];
  private overlay: Overlay | undefined;
  private readonly resize: ResizeObserver;
  /** The table without balls, drawn once per canvas size. */
  private background: HTMLCanvasElement | null = null;
  /** How each ball is turned, kept between shots (the animator turns them). */
  readonly orientations = new Orientations();

  constructor(parent: HTMLElement, table: string, label: string) {
    this.spec = tableSpec(table);
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'table';
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', label);
    this.canvas.tabIndex = 0;
    parent.append(this.canvas);
    this.resize = new ResizeObserver(() => this.fit());
    this.resize.observe(parent);
    this.fit();
  }

  /** Metres per CSS pixel, the other way round. */
  get pixelsPerMetre(): number {
    return this.scale;
  }

  destroy(): void {
    this.resize.disconnect();
    this.canvas.remove();
  }

  /** Sizes the canvas to its container's width at the table's aspect, in device pixels. */
  fit(): void {
    const parent = this.canvas.parentElement;
    if (!parent) return;
    const w = Math.max(200, parent.clientWidth);
    this.turned = matchMedia(UPRIGHT_PHONE).matches;
    const long = this.spec.length + 2 * RAIL;
    const short = this.spec.width + 2 * RAIL;
    const worldW = this.turned ? short : long;
    const worldH = this.turned ? long : short;
    // At most 70% of the window's height, and on a short window low enough that the controls
    // below it fit on the same screen; on a phone on its side (controls beside it) the height
    // below what stands above it, so that a touch on it never scrolls the page; turned upright,
    // the screen's height (the page scrolls to it).
    const top = parent.getBoundingClientRect().top + window.scrollY;
    const room = this.turned
      ? window.innerHeight - 16
      : matchMedia(SIDEWAYS_PHONE).matches
        ? window.innerHeight - top - 8
        : Math.min(window.innerHeight * 0.7, window.innerHeight - 200);
    const h = Math.min(w * (worldH / worldW), Math.max(150, room));
    const cssW = Math.min(w, h * (worldW / worldH));
    const dpr = window.devicePixelRatio || 1;
    this.canvas.style.width = `${cssW}px`;
    this.canvas.style.height = `${h}px`;
    this.canvas.width = Math.round(cssW * dpr);
    this.canvas.height = Math.round(h * dpr);
    this.scale = cssW / worldW;
    // The balls' size on screen, for tests and tools: numbers need a few pixels to be read.
    this.canvas.dataset.ballRadius = (this.spec.ballRadius * this.scale).toFixed(1);
    this.background = null;
    this.draw(this.balls);
  }

  setOverlay(overlay: Overlay | undefined): void {
    this.overlay = overlay;
  }

  /** Draws the table and the balls (each turned as `orientations` holds unless it says), then the overlay. */
  draw(balls: readonly DrawnBall[]): void {
    this.balls = balls;
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const dpr = this.canvas.width / (parseFloat(this.canvas.style.width) || this.canvas.width);
    const toWorld = () => this.toWorldTransform(ctx, dpr);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    const bg = this.tableImage(dpr);
    if (bg) ctx.drawImage(bg, 0, 0);
    toWorld();
    if (!bg) drawTable(ctx, this.spec);
    const R = this.spec.ballRadius;
    // Dropping balls first: they are below the cloth's level, under any ball still rolling.
    for (const b of balls) if (b.sink) drawBall(ctx, b.q ? b : { ...b, q: this.orientations.get(b.id) }, R, this.spec.name, this.turned);
    for (const b of balls) drawShadow(ctx, b, R);
    for (const b of balls) if (!b.sink) drawBall(ctx, b.q ? b : { ...b, q: this.orientations.get(b.id) }, R, this.spec.name, this.turned);
    this.overlay?.(ctx, this);
  }

  /** Metres to device pixels, y up, the origin at the centre; turned a quarter upright on a phone. */
  private toWorldTransform(c: CanvasRenderingContext2D, dpr: number): void {
    const k = this.scale * dpr;
    if (this.turned) c.setTransform(0, -k, -k, 0, c.canvas.width / 2, c.canvas.height / 2);
    else c.setTransform(k, 0, 0, -k, c.canvas.width / 2, c.canvas.height / 2);
  }

  /** The table drawn once at this size (a copy per frame is cheaper than drawing it). */
  private tableImage(dpr: number): HTMLCanvasElement | null {
    if (this.background && this.background.width === this.canvas.width && this.background.height === this.canvas.height) return this.background;
    const bg = document.createElement('canvas');
    bg.width = this.canvas.width;
    bg.height = this.canvas.height;
    const c = bg.getContext('2d');
    if (!c) return null;
    this.toWorldTransform(c, dpr);
    drawTable(c, this.spec);
    this.background = bg;
    return bg;
  }

  /** A step on the screen (right, up) as a step on the table: an arrow key moves a ball the way it points. */
  screenStep(right: number, up: number): { x: number; y: number } {
    return this.turned ? { x: up, y: -right } : { x: right, y: up };
  }

  /** The world point under a pointer event's client coordinates. */
  toWorld(clientX: number, clientY: number): { x: number; y: number } {
    const r = this.canvas.getBoundingClientRect();
    const dx = (clientX - r.left - r.width / 2) / this.scale;
    const dy = (clientY - r.top - r.height / 2) / this.scale;
    return this.turned ? { x: -dy, y: -dx } : { x: dx, y: -dy };
  }
}
