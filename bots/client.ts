// A small client of the game protocol (docs/protocol.md) over `ws`: requests answered by `re`,
// pushed messages by listener, iterator or waitFor. It connects to the one URL it is given, nothing else.
import { WebSocket } from 'ws';
import { RATE_BURST, RATE_PER_SECOND, type ClientMessage, type ServerMessage } from '../shared/protocol/index.ts';

export type Outgoing = ClientMessage;
type Listener = (msg: ServerMessage) => void;

/** This client's own send budget, under the server's limit (RATE_PER_SECOND, RATE_BURST) with room to spare. */
const BUDGET_PER_SECOND = RATE_PER_SECOND * 0.8;
const BUDGET_BURST = RATE_BURST / 4;

/** A request the server refused: its error message's code and text. */
export class ProtocolError extends Error {
  override readonly name = 'ProtocolError';
  constructor(
    readonly code: string,
    message: string,
  ) {
    super(`${code}: ${message}`);
  }
}

export class ProtocolClient {
  private readonly listeners = new Set<Listener>();
  private readonly closeListeners = new Set<(code: number) => void>();
  private closeCode: number | undefined;
  /** Frames waiting for the budget, and the budget: a token bucket like the server's, with margin. */
  private readonly queue: { text: string; onSent: (() => void) | undefined }[] = [];
  private tokens = BUDGET_BURST;
  private refilledAt = performance.now();
  private drainTimer: NodeJS.Timeout | undefined;
  private nextId = 1;
  /** Resolves once the socket has closed, with its close code. */
  readonly closed: Promise<number>;

  private constructor(private readonly socket: WebSocket) {
    this.closed = new Promise((resolve) => {
      socket.once('close', (code: number) => {
        this.closeCode = code;
        resolve(code);
        for (const l of [...this.closeListeners]) l(code);
        this.closeListeners.clear();
        clearTimeout(this.drainTimer);
        this.queue.length = 0;
      });
    });
    socket.on('message', (data, isBinary) => {
      if (isBinary) return;
      let msg: unknown;
      try {
        msg = JSON.parse(data.toString());
      } catch {
        return; // the server sends JSON only; anything else is not ours to read
      }
      if (typeof msg !== 'object' || msg === null || typeof (msg as { type?: unknown }).type !== 'string') return;
      for (const l of [...this.listeners]) {
        try {
          l(msg as ServerMessage);
        } catch (err) {
          // One listener's bug must not take the socket (and every other bot in the process) down.
          console.error(`bots: a message listener threw: ${err instanceof Error ? err.stack : String(err)}`);
        }
      }
    });
    // Errors also close the socket; `closed` reports it, so they need no handler beyond this.
    socket.on('error', () => {});
  }

  /** Opens a socket to `url` (ws:// or wss://) and resolves once it is open. */
  static connect(url: string, timeoutMs = 10_000): Promise<ProtocolClient> {
    if (!/^wss?:\/\//.test(url)) return Promise.reject(new Error(`not a WebSocket URL: ${url}`));
    return new Promise((resolve, reject) => {
      const socket = new WebSocket(url, { handshakeTimeout: timeoutMs });
      const fail = (err: Error) => {
        socket.terminate();
        reject(err);
      };
      socket.once('open', () => {
        socket.off('error', fail);
        resolve(new ProtocolClient(socket));
      });
      socket.once('error', fail);
    });
  }

  get open(): boolean {
    return this.socket.readyState === WebSocket.OPEN;
  }

  /**
   * Sends a message as is, or queues it while this socket is over its own budget (the server
   * closes a socket that sends too fast); `onSent` runs when it goes out. Returns false when the
   * socket is no longer open.
   */
  send(msg: Outgoing, onSent?: () => void): boolean {
    if (!this.open) return false;
    this.queue.push({ text: JSON.stringify(msg), onSent });
    this.drain();
    return true;
  }

  /** Sends what the budget allows now, and wakes up for the rest when a token is due. */
  private drain(): void {
    if (this.drainTimer) return;
    const now = performance.now();
    this.tokens = Math.min(BUDGET_BURST, this.tokens + ((now - this.refilledAt) / 1000) * BUDGET_PER_SECOND);
    this.refilledAt = now;
    while (this.queue.length > 0 && this.tokens >= 1 && this.open) {
      const next = this.queue.shift()!;
      this.tokens--;
      this.socket.send(next.text);
      next.onSent?.();
    }
    if (this.queue.length > 0 && this.open) {
      const wait = ((1 - this.tokens) / BUDGET_PER_SECOND) * 1000;
      this.drainTimer = setTimeout(() => {
        this.drainTimer = undefined;
        this.drain();
      }, Math.ceil(wait));
    }
  }

  /** A fresh request id for this socket. */
  newId(): string {
    return `r${this.nextId++}`;
  }

  /** Calls `listener` with every message from now on; returns the function that stops it. */
  onMessage(listener: Listener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Sends `msg` with a fresh id and resolves with the message that carries it back as `re`; rejects on an error for it. */
  request(msg: Outgoing, timeoutMs = 10_000): Promise<ServerMessage> {
    if (!this.open) return Promise.reject(new Error('the socket is closed'));
    const id = this.newId();
    const answer = this.waitFor((m) => m.re === id, timeoutMs);
    this.send({ ...msg, id });
    return answer.then((m) => {
      if (m.type === 'error') throw new ProtocolError(m.code, m.message);
      return m;
    });
  }

  /** Resolves with the first message from now on that `predicate` accepts; rejects on timeout or close. */
  waitFor<T extends ServerMessage = ServerMessage>(
    predicate: ((m: ServerMessage) => m is T) | ((m: ServerMessage) => boolean),
    timeoutMs = 10_000,
  ): Promise<T> {
    return new Promise<T>((resolve, reject) => {
      const finish = () => {
        clearTimeout(timer);
        stopMessages();
        stopClose();
      };
      const stopMessages = this.onMessage((m) => {
        if (!predicate(m)) return;
        finish();
        resolve(m as T);
      });
      const stopClose = this.onClose((code) => {
        finish();
        reject(new Error(`the socket closed (${code})`));
      });
      const timer = setTimeout(() => {
        finish();
        reject(new Error(`no matching message within ${timeoutMs} ms`));
      }, timeoutMs);
    });
  }

  /** Calls `listener` once the socket closes (at once if it has); returns the function that stops it. */
  onClose(listener: (code: number) => void): () => void {
    if (this.closeCode !== undefined) {
      listener(this.closeCode);
      return () => {};
    }
    this.closeListeners.add(listener);
    return () => this.closeListeners.delete(listener);
  }

  /** Every message from now on, until the socket closes. */
  async *messages(): AsyncGenerator<ServerMessage> {
    const queue: ServerMessage[] = [];
    let wake: (() => void) | undefined;
    let ended = false;
    const stop = this.onMessage((m) => {
      queue.push(m);
      wake?.();
    });
    const stopClose = this.onClose(() => {
      ended = true;
      wake?.();
    });
    try {
      for (;;) {
        const m = queue.shift();
        if (m !== undefined) yield m;
        else if (ended) return;
        else await new Promise<void>((r) => (wake = r));
      }
    } finally {
      stop();
      stopClose();
    }
  }

  /** Closes the socket (normal closure) and resolves once it is closed; cuts it after `graceMs`. */
  close(graceMs = 2000): Promise<void> {
    if (this.socket.readyState === WebSocket.CLOSED) return Promise.resolve();
    this.socket.close(1000);
    const cut = setTimeout(() => this.socket.terminate(), graceMs);
    return this.closed.then(() => clearTimeout(cut));
  }
}
