// The cue stick: the stroke's geometry (how far a drag pulls it back, which power that is, where a
// press grabs it) as pure functions of plain numbers, and its drawing along the aim.

/** The stroke's speeds (m/s): the softest and the hardest. */
export const MIN_SPEED = 0.3;
export const MAX_SPEED = 10;

/** The pull (m of table) that gives full power; the gap between tip and ball is the pull. */
export const MAX_PULL = 0.4;
/** ...but never less than this many CSS pixels, so that a small table (a phone) keeps fine control. */
export const FULL_PX = 150;

/** The pull (m) for full power on a table drawn at `pixelsPerMetre`. */
export function fullPull(pixelsPerMetre: number): number {
  return Math.max(MAX_PULL, FULL_PX / pixelsPerMetre);
}
/** A drag shorter than this many CSS pixels back from where it started cancels the stroke. */
export const CANCEL_PX = 10;
/** The stick drawn (m): shorter than a real cue (1.45 m) so that less of it leaves the table. */
const STICK = 1.2;

/**
 * The speed (m/s) of a stroke pulled back `pull` metres, or null when the pull is too short to
 * count (`cancel` metres: a release there cancels). Proportional to the pull, from MIN_SPEED to
 * MAX_SPEED at `full` metres.
 */
export function pullToSpeed(pull: number, cancel = 0, full = MAX_PULL): number | null {
  if (!(pull > cancel) || !(pull > 0)) return null;
  const v = (MAX_SPEED * pull) / full;
  return Math.round(Math.min(MAX_SPEED, Math.max(MIN_SPEED, v)) * 100) / 100;
}

/** The gap between the tip and the ball at a speed: the pull that gives that speed. */
export function speedToGap(speed: number, full = MAX_PULL): number {
  return (full * Math.min(MAX_SPEED, Math.max(0, speed))) / MAX_SPEED;
}

/** How far `to` lies behind `from` along the stroke (opposite the heading), in metres; never below 0. */
export function pullBack(heading: number, from: { x: number; y: number }, to: { x: number; y: number }): number {
  return Math.max(0, -((to.x - from.x) * Math.cos(heading) + (to.y - from.y) * Math.sin(heading)));
}

/** A drag this many CSS pixels long shows which way it goes (a ball in hand: placed or stroked). */
export const DECIDE_PX = 6;

/**
 * Whether a drag from `from` to `to` goes back from the aim (within 30° of the line behind the
 * ball): on a ball in hand such a drag pulls the cue, any other moves the ball.
 */
export function goesBack(heading: number, from: { x: number; y: number }, to: { x: number; y: number }): boolean {
  const d = Math.hypot(to.x - from.x, to.y - from.y);
  return d > 0 && pullBack(heading, from, to) / d >= Math.cos(Math.PI / 6);
}

/**
 * Whether a press at `p` grabs the stick drawn behind the ball at `cue` (heading, tip gap): along
 * the stick and within `reach` metres of its axis.
 */
export function onStick(p: { x: number; y: number }, cue: { x: number; y: number }, heading: number, R: number, gap: number, reach: number): boolean {
  const dx = p.x - cue.x;
  const dy = p.y - cue.y;
  const back = -(dx * Math.cos(heading) + dy * Math.sin(heading));
  const across = Math.abs(-dx * Math.sin(heading) + dy * Math.cos(heading));
  return back > R && back < R + gap + STICK && across < reach;
}

/** Power in plain words, for the meter. */
export function powerWords(speed: number): string {
  const f = (speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED);
  const word = f < 0.08 ? 'Very soft' : f < 0.25 ? 'Soft' : f < 0.45 ? 'Medium' : f < 0.7 ? 'Firm' : f < 0.9 ? 'Hard' : 'Full power';
  return `${word}, ${Math.round(powerFraction(speed) * 100)}%`;
}

/** 0 at MIN_SPEED, 1 at MAX_SPEED. */
export function powerFraction(speed: number): number {
  return Math.min(1, Math.max(0, (speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED)));
}

/**
 * Draws the stick in world coordinates (m, y up): its tip `gap` behind the ball's surface on the
 * line opposite the heading, shifted sideways by the side spin (the tip strikes off centre), with
 * a soft shadow beneath.
 */
export function drawCue(ctx: CanvasRenderingContext2D, cue: { x: number; y: number }, heading: number, R: number, gap: number, side: number): void {
  const c = Math.cos(heading);
  const s = Math.sin(heading);
  // Along the stick (from the tip to the butt) and across it (the ball's right as the player sees it).
  const ax = -c;
  const ay = -s;
  const rx = s;
  const ry = -c;
  const off = side * R;
  const tip = { x: cue.x + ax * (R + gap) + rx * off, y: cue.y + ay * (R + gap) + ry * off };
  /** The quadrilateral from `a` to `b` metres along the stick, `wa`/`wb` wide there. */
  const piece = (a: number, b: number, wa: number, wb: number, dx = 0, dy = 0) => {
    ctx.beginPath();
    ctx.moveTo(tip.x + ax * a + rx * wa / 2 + dx, tip.y + ay * a + ry * wa / 2 + dy);
    ctx.lineTo(tip.x + ax * b + rx * wb / 2 + dx, tip.y + ay * b + ry * wb / 2 + dy);
    ctx.lineTo(tip.x + ax * b - rx * wb / 2 + dx, tip.y + ay * b - ry * wb / 2 + dy);
    ctx.lineTo(tip.x + ax * a - rx * wa / 2 + dx, tip.y + ay * a - ry * wa / 2 + dy);
    ctx.closePath();
    ctx.fill();
  };
  // A tip of 13 mm widening to a butt of 30 mm.
  const tipW = 0.013;
  const buttW = 0.03;
  const w = (d: number) => tipW + ((buttW - tipW) * d) / STICK;
  ctx.fillStyle = 'rgba(0,0,0,0.28)';
  piece(0, STICK, tipW, buttW, 0.008, -0.012);
  ctx.fillStyle = '#3d7fd9'; // chalked tip
  piece(0, 0.008, tipW, w(0.008));
  ctx.fillStyle = '#f2efe6'; // ferrule
  piece(0.008, 0.03, w(0.008), w(0.03));
  ctx.fillStyle = '#e3c58d'; // maple shaft
  piece(0.03, STICK * 0.6, w(0.03), w(STICK * 0.6));
  ctx.fillStyle = '#1c1a18'; // joint ring
  piece(STICK * 0.6, STICK * 0.6 + 0.012, w(STICK * 0.6), w(STICK * 0.6 + 0.012));
  ctx.fillStyle = '#6b3a1f'; // butt
  piece(STICK * 0.6 + 0.012, STICK - 0.03, w(STICK * 0.6 + 0.012), w(STICK - 0.03));
  ctx.fillStyle = '#111'; // bumper
  piece(STICK - 0.03, STICK, w(STICK - 0.03), buttW);
}
