// The page's connection to the game server: one WebSocket at /ws speaking shared/protocol, a guest
// identity kept in the browser (its token), requests answered by `re`, and reconnection with
// backoff that says hello again with the token and resumes whatever the page was doing.
import type { ClientMessage, PlayerRef, ServerMessage } from '../../shared/protocol/index.ts';

const TOKEN_KEY = 'baize.token';
const BACKOFF_MS = [250, 500, 1000, 2000, 4000, 8000];

export type SessionStatus = 'connecting' | 'online' | 'reconnecting';
type Listener = (m: ServerMessage) => void;
type Outgoing = ClientMessage extends infer M ? (M extends { id?: unknown } ? Omit<M, 'id'> : M) : never;

export class Session {
  player: PlayerRef | null = null;
  status: SessionStatus = 'connecting';
  private socket: WebSocket | null = null;
  private readonly listeners = new Set<Listener>();
  private readonly statusListeners = new Set<(s: SessionStatus) => void>();
  /** Messages to send again after every welcome (the lobby subscription, a room watched). */
  private readonly resumes = new Map<string, Outgoing>();
  private attempts = 0;
  private nextId = 1;

  constructor(private readonly url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`) {
    this.open();
  }

  onMessage(l: Listener): () => void {
    this.listeners.add(l);
    return () => this.listeners.delete(l);
  }

  onStatus(l: (s: SessionStatus) => void): () => void {
    this.statusListeners.add(l);
    l(this.status);
    return () => this.statusListeners.delete(l);
  }

  /** Sends now if online (else drops it: moves are never queued across a reconnect). */
  send(msg: Outgoing): string | undefined {
    if (this.status !== 'online' || !this.socket) return undefined;
    const id = `c${this.nextId++}`;
    this.socket.send(JSON.stringify({ ...msg, id }));
    return id;
  }

  /** Sends and resolves with the reply (or the error) that carries the request back. */
  request(msg: Outgoing, timeoutMs = 10_000): Promise<ServerMessage> {
    return new Promise((resolve, reject) => {
      const id = this.send(msg);
      if (id === undefined) return reject(new Error('not connected'));
      const timer = setTimeout(() => {
        stop();
        reject(new Error('no answer'));
      }, timeoutMs);
      const stop = this.onMessage((m) => {
        if (m.re !== id) return;
        clearTimeout(timer);
        stop();
        resolve(m);
      });
    });
  }

  /** Sends a message now and again after every reconnection, until forgotten. */
  keep(key: string, msg: Outgoing): void {
    this.resumes.set(key, msg);
    this.send(msg);
  }

  forget(key: string): void {
    this.resumes.delete(key);
  }

  private setStatus(s: SessionStatus): void {
    this.status = s;
    for (const l of this.statusListeners) l(s);
  }

  private open(): void {
    const socket = new WebSocket(this.url);
    this.socket = socket;
    socket.onopen = () => {
      const token = localStorage.getItem(TOKEN_KEY);
      socket.send(JSON.stringify({ type: 'hello', id: 'hello', ...(token ? { token } : {}) }));
    };
    socket.onmessage = (e) => {
      let m: ServerMessage;
      try {
        m = JSON.parse(String(e.data)) as ServerMessage;
      } catch {
        return;
      }
      if (m.type === 'player') this.player = m.player;
      if (m.re === 'hello') {
        if (m.type === 'error' && m.code === 'bad-token') {
          // A token this server does not know (a new database): start again as a new guest.
          localStorage.removeItem(TOKEN_KEY);
          socket.send(JSON.stringify({ type: 'hello', id: 'hello' }));
          return;
        }
        if (m.type === 'welcome') {
          localStorage.setItem(TOKEN_KEY, m.token);
          this.player = m.player;
          this.attempts = 0;
          this.setStatus('online');
          for (const msg of this.resumes.values()) this.send(msg);
        }
      }
      for (const l of [...this.listeners]) l(m);
    };
    socket.onclose = () => {
      if (this.socket !== socket) return;
      this.socket = null;
      this.setStatus('reconnecting');
      const delay = BACKOFF_MS[Math.min(this.attempts++, BACKOFF_MS.length - 1)]!;
      setTimeout(() => this.open(), delay * (0.75 + Math.random() / 2));
    };
  }
}

/** The token kept in this browser, for the HTTP API's practice submission. */
export function storedToken(): string | null {
  return localStorage.getItem(TOKEN_KEY);
}
