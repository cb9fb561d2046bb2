// Real Chromium from Debian's package, driven by playwright-core; never a downloaded browser.
// Without it the browser tests skip with a message, unless BAIZE_REQUIRE_BROWSER=1 (CI) makes
// them mandatory.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { chromium, type Browser } from 'playwright-core';
import { afterAll, beforeAll } from 'vitest';
import { startServerProcess, tempDir, type ServerProcess } from './server-process.ts';

export const CHROMIUM_PATH = '/usr/bin/chromium';
export const REQUIRE_BROWSER = process.env.BAIZE_REQUIRE_BROWSER === '1';

/** True when the tests should run; logs why they skip otherwise. */
export function chromiumAvailable(): boolean {
  if (existsSync(CHROMIUM_PATH)) return true;
  if (REQUIRE_BROWSER) return true; // run and fail loudly: CI promised a browser
  console.warn(`browser tests skipped: no Chromium at ${CHROMIUM_PATH} (apt-get install chromium; BAIZE_REQUIRE_BROWSER=1 makes this a failure)`);
  return false;
}

export async function launchChromium(): Promise<Browser> {
  if (!existsSync(CHROMIUM_PATH)) {
    throw new Error(`BAIZE_REQUIRE_BROWSER=1 but no Chromium at ${CHROMIUM_PATH}: install Debian's chromium package`);
  }
  return chromium.launch({
    executablePath: CHROMIUM_PATH,
    headless: true,
    // This machine has no network beyond loopback: keep Chromium from reaching out.
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
}

/**
 * For a describe block: a real server on a fresh database (given to `prepare` first, if any) and
 * Chromium, started before its tests and stopped after; read them through the returned getters
 * inside the tests.
 */
export function serverAndChromium(prepare?: (dbPath: string) => void): { readonly browser: Browser; readonly server: ServerProcess } {
  let browser: Browser | undefined;
  let server: ServerProcess | undefined;
  beforeAll(async () => {
    const dbPath = join(tempDir(), 'baize.db');
    prepare?.(dbPath);
    server = await startServerProcess({ BAIZE_DB: dbPath });
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await server?.stop();
  });
  return {
    get browser() {
      return browser!;
    },
    get server() {
      return server!;
    },
  };
}
