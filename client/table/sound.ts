// The table's sounds, synthesised with Web Audio from an outcome's events (no sound files): a
// tap of the cue at the strike, a bright click for ball on ball, a dull thud for a cushion, a
// rolling drop for a pocket, each as loud as its impact was fast. The schedule is a pure function
// of the outcome; the player places it on the animation's clock (its speed, its skips).
import { sampleOutcome, type Outcome } from '../../shared/physics/index.ts';
import { h } from '../dom.ts';

export type SoundKind = 'cue' | 'ball' | 'cushion' | 'pocket';

export interface SoundCue {
  /** Seconds since the strike, on the outcome's clock. */
  readonly t: number;
  readonly kind: SoundKind;
  /** 0..1. */
  readonly gain: number;
}

/** Impacts slower than this (m/s) are not heard: resting contacts, balls pressed in a cluster. */
const QUIET = 0.03;
/** At most this many sounds a shot (the loudest kept): a break's cluster touches add nothing. */
const MAX_CUES = 160;

/** How loud an impact of `kind` at `speed` m/s sounds, 0..1. */
export function impactGain(kind: SoundKind, speed: number): number {
  const v = Math.abs(speed);
  switch (kind) {
    case 'cue':
      return Math.min(1, 0.15 + v / 8);
    case 'ball':
      return Math.min(1, (v / 4) ** 0.8);
    case 'cushion':
      return Math.min(1, (v / 3) ** 0.8);
    case 'pocket':
      return Math.min(1, 0.3 + v / 4);
  }
}

/**
 * The sounds of a shot: the cue's tap at t = 0 (from the struck ball's speed), then each
 * ball-ball, cushion and pocket event, as loud as its speed along the contact normal (a pocket's
 * from the ball's speed as it drops, sampled from its path).
 */
export function soundSchedule(outcome: Outcome): SoundCue[] {
  const cues: SoundCue[] = [];
  const start = sampleOutcome(outcome, 0);
  const struck = Math.max(0, ...start.map((b) => Math.hypot(b.vx, b.vy)));
  if (struck > 0) cues.push({ t: 0, kind: 'cue', gain: impactGain('cue', struck) });
  for (const e of outcome.events) {
    if (e.kind === 'ball' || e.kind === 'cushion') {
      const v = Math.abs(e.speed ?? 0);
      if (v >= QUIET) cues.push({ t: e.t, kind: e.kind, gain: impactGain(e.kind, v) });
    } else if (e.kind === 'pocket') {
      // Just before the drop: at the event itself the ball is already in the pocket.
      const b = sampleOutcome(outcome, Math.max(0, e.t - 1e-4)).find((x) => x.id === e.balls[0]);
      cues.push({ t: e.t, kind: 'pocket', gain: impactGain('pocket', b ? Math.hypot(b.vx, b.vy) : 0) });
    }
  }
  if (cues.length > MAX_CUES) {
    const floor = [...cues].sort((a, b) => b.gain - a.gain)[MAX_CUES - 1]!.gain;
    return cues.filter((c) => c.gain >= floor).slice(0, MAX_CUES);
  }
  return cues;
}

/** When each cue sounds, in seconds from now, for an animation at `speed` from `from` s: the ones still to come. */
export function cueTimes(cues: readonly SoundCue[], from: number, speed: number): { at: number; cue: SoundCue }[] {
  return cues.filter((c) => c.t >= from - 1e-9).map((cue) => ({ at: (cue.t - from) / speed, cue }));
}

const KEY = 'baize.sound';
let enabled = readSetting();
let audio: AudioContext | null = null;
let noise: AudioBuffer | null = null;

function readSetting(): boolean {
  try {
    return globalThis.localStorage?.getItem(KEY) !== 'off';
  } catch {
    return true;
  }
}

/** Whether sound is on (the player's choice, remembered in this browser; on by default). */
export function soundOn(): boolean {
  return enabled;
}

/**
 * The audio context, made on a user gesture (browsers keep audio off until one): the first
 * press or key on the page after the sound was turned on.
 */
function unlock(): void {
  if (!enabled) return;
  const Ctor = globalThis.AudioContext ?? (globalThis as { webkitAudioContext?: typeof AudioContext }).webkitAudioContext;
  if (!Ctor) return;
  if (!audio) {
    try {
      audio = new Ctor();
    } catch {
      return;
    }
  }
  if (audio.state === 'suspended') void audio.resume().catch(() => {});
}

let listening = false;
function listenForGesture(): void {
  if (listening || typeof document === 'undefined') return;
  listening = true;
  document.addEventListener('pointerdown', unlock, true);
  document.addEventListener('keydown', unlock, true);
}

/** The "Sound" toggle (aria-pressed: true when on), remembered in localStorage. */
export function soundToggle(): HTMLButtonElement {
  listenForGesture();
  const button = h('button', { type: 'button', className: 'sound-toggle', 'aria-pressed': String(enabled), title: 'Sound on or off' }, 'Sound');
  button.addEventListener('click', () => {
    enabled = !enabled;
    try {
      localStorage.setItem(KEY, enabled ? 'on' : 'off');
    } catch {
      // (Storage refused: the choice holds for this page only.)
    }
    button.setAttribute('aria-pressed', String(enabled));
    if (enabled) unlock();
    else players.forEach((p) => p.stop());
  });
  return button;
}

const players = new Set<SoundPlayer>();

/** Plays a shot's sounds on the animation's clock; stop() silences what is still to come. */
export class SoundPlayer {
  private bus: GainNode | null = null;

  constructor() {
    players.add(this);
  }

  /** Schedules the cues still to come of an animation running at `speed` from `from` s, after stopping the previous ones. */
  play(cues: readonly SoundCue[], from: number, speed: number): void {
    this.stop();
    if (!enabled || !audio || audio.state !== 'running') return;
    const ctx = audio;
    const bus = ctx.createGain();
    bus.gain.value = 0.5;
    bus.connect(ctx.destination);
    this.bus = bus;
    const now = ctx.currentTime + 0.01;
    for (const { at, cue } of cueTimes(cues, from, speed)) voice(ctx, bus, cue.kind, now + at, cue.gain);
  }

  stop(): void {
    this.bus?.disconnect();
    this.bus = null;
  }

  destroy(): void {
    this.stop();
    players.delete(this);
  }
}

function noiseBuffer(ctx: AudioContext): AudioBuffer {
  if (noise && noise.sampleRate === ctx.sampleRate) return noise;
  noise = ctx.createBuffer(1, Math.round(ctx.sampleRate * 0.5), ctx.sampleRate);
  const d = noise.getChannelData(0);
  for (let i = 0; i < d.length; i++) d[i] = Math.random() * 2 - 1;
  return noise;
}

/** A decaying tone: `freq` (gliding to `to`), peak `gain` at `at`, down by 60 dB after `decay` s. */
function tone(ctx: AudioContext, out: AudioNode, type: OscillatorType, freq: number, to: number, at: number, gain: number, decay: number): void {
  const o = ctx.createOscillator();
  const g = ctx.createGain();
  o.type = type;
  o.frequency.setValueAtTime(freq, at);
  if (to !== freq) o.frequency.exponentialRampToValueAtTime(to, at + decay);
  g.gain.setValueAtTime(0.0001, at);
  g.gain.exponentialRampToValueAtTime(Math.max(0.0002, gain), at + 0.002);
  g.gain.exponentialRampToValueAtTime(0.0001, at + decay);
  o.connect(g).connect(out);
  o.start(at);
  o.stop(at + decay + 0.02);
}

/** A burst of filtered noise. */
function hiss(ctx: AudioContext, out: AudioNode, filter: BiquadFilterType, freq: number, at: number, gain: number, decay: number): void {
  const src = ctx.createBufferSource();
  src.buffer = noiseBuffer(ctx);
  const f = ctx.createBiquadFilter();
  f.type = filter;
  f.frequency.value = freq;
  const g = ctx.createGain();
  g.gain.setValueAtTime(0.0001, at);
  g.gain.exponentialRampToValueAtTime(Math.max(0.0002, gain), at + 0.002);
  g.gain.exponentialRampToValueAtTime(0.0001, at + decay);
  src.connect(f).connect(g).connect(out);
  src.start(at, Math.random() * 0.2);
  src.stop(at + decay + 0.02);
}

function voice(ctx: AudioContext, out: AudioNode, kind: SoundKind, at: number, gain: number): void {
  switch (kind) {
    case 'cue': // leather on phenolic: a soft, woody tap
      tone(ctx, out, 'triangle', 620, 480, at, gain * 0.6, 0.05);
      hiss(ctx, out, 'bandpass', 1800, at, gain * 0.35, 0.02);
      break;
    case 'ball': // ball on ball: a short, bright click, brighter when harder
      tone(ctx, out, 'sine', 2600 + 900 * gain, 2400 + 900 * gain, at, gain * 0.7, 0.045);
      hiss(ctx, out, 'highpass', 3000, at, gain * 0.45, 0.012);
      break;
    case 'cushion': // rubber and cloth: a dull thud
      tone(ctx, out, 'sine', 150, 90, at, gain * 0.9, 0.12);
      hiss(ctx, out, 'lowpass', 500, at, gain * 0.4, 0.05);
      break;
    case 'pocket': // a drop and a roll down the pocket: knocks falling in pitch, and a rumble
      tone(ctx, out, 'sine', 260, 180, at, gain * 0.8, 0.09);
      tone(ctx, out, 'sine', 200, 140, at + 0.08, gain * 0.5, 0.09);
      tone(ctx, out, 'sine', 160, 110, at + 0.17, gain * 0.3, 0.1);
      hiss(ctx, out, 'lowpass', 350, at, gain * 0.35, 0.3);
      break;
  }
}
