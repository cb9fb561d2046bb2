// Debian's firefox-esr, headless, run as a plain process: it loads a page that reports back to a
// local test server (playwright-core drives only patched Firefox builds, so none is used here).
import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { REQUIRE_BROWSER } from './browser.ts';

export const FIREFOX_PATHS = ['/usr/bin/firefox-esr', '/usr/bin/firefox'];

export function firefoxPath(): string | undefined {
  return FIREFOX_PATHS.find((p) => existsSync(p));
}

export function firefoxAvailable(): boolean {
  if (firefoxPath()) return true;
  if (REQUIRE_BROWSER) return true;
  console.warn(`Firefox tests skipped: no firefox-esr at ${FIREFOX_PATHS.join(' or ')} (apt-get install firefox-esr; BAIZE_REQUIRE_BROWSER=1 makes this a failure)`);
  return false;
}

// Keep a headless Firefox from reaching out: this machine has no network beyond loopback.
const PREFS = {
  'app.update.enabled': false,
  'browser.shell.checkDefaultBrowser': false,
  'browser.startup.homepage_override.mstone': 'ignore',
  'browser.aboutwelcome.enabled': false,
  'datareporting.policy.dataSubmissionEnabled': false,
  'datareporting.healthreport.uploadEnabled': false,
  'toolkit.telemetry.enabled': false,
  'network.captive-portal-service.enabled': false,
  'network.connectivity-service.enabled': false,
  'extensions.update.enabled': false,
  'browser.safebrowsing.malware.enabled': false,
  'browser.safebrowsing.phishing.enabled': false,
  'browser.safebrowsing.downloads.enabled': false,
  'browser.region.network.url': '',
  'browser.search.geoip.url': '',
};

export function launchFirefox(url: string): ChildProcess {
  const path = firefoxPath();
  if (!path) throw new Error(`BAIZE_REQUIRE_BROWSER=1 but no Firefox at ${FIREFOX_PATHS.join(' or ')}: install Debian's firefox-esr package`);
  const profile = mkdtempSync(join(tmpdir(), 'baize-firefox-'));
  writeFileSync(join(profile, 'user.js'), Object.entries(PREFS).map(([k, v]) => `user_pref(${JSON.stringify(k)}, ${JSON.stringify(v)});`).join('\n'));
  return spawn(path, ['--headless', '--no-remote', '--new-instance', '--profile', profile, url], {
    stdio: 'ignore',
    env: { ...process.env, MOZ_HEADLESS: '1' },
  });
}
