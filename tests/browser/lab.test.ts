import { describe, expect, it } from 'vitest';
import type { Browser, Page } from 'playwright-core';
import { PAPER, PUBLISHED } from '../../shared/scenes/index.ts';
import { chromiumAvailable, serverAndChromium } from '../support/browser.ts';

/** The kernel's rebound written beside each published point's label: "...; kernel: S m/s at A°". */
function kernelValues(label: string): { speed: number; angle: number } {
  const m = /kernel: ([\d.]+) m\/s at ([\d.]+)°/.exec(label);
  if (!m) throw new Error(`no kernel value in "${label}"`);
  return { speed: Number(m[1]), angle: Number(m[2]) };
}

async function open(browser: Browser, url: string): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (err) => errors.push(err.message));
  page.on('console', (m) => (m.type() === 'error' ? errors.push(m.text()) : undefined));
  await page.goto(url);
  await page.locator('#fig12 svg').waitFor();
  return { page, errors };
}

describe.skipIf(!chromiumAvailable())('the physics lab in Chromium', () => {
  const env = serverAndChromium();

  it('draws Figs. 9, 10 and 12 with the published values on them, reproduced within their accuracy', async () => {
    const { page, errors } = await open(env.browser, `${env.server.url}/lab`);
    for (const id of ['fig9', 'fig10', 'fig12']) {
      expect(await page.locator(`figure#${id} svg polyline`).count()).toBeGreaterThan(1);
      expect(await page.locator(`figure#${id} figcaption`).textContent()).toMatch(/Fig\./);
    }
    // Axes with units and a legend entry for every curve.
    const fig9 = await page.locator('#fig9 svg').innerHTML();
    expect(fig9).toContain('rebound speed (m/s)');
    expect(fig9).toContain('incidence α (°)');
    for (const k of [-1, 0, 1, 2]) expect(fig9).toContain(`topspin k = ${k}`);
    for (const [fig, published] of [['fig9', PUBLISHED.filter((p) => p.figure === 9)], ['fig12', PUBLISHED.filter((p) => p.figure === 12)]] as const) {
      for (const p of published) {
        const marks = page.locator(`#${fig} circle[data-mark*="${p.label}"] title`);
        expect(await marks.count()).toBeGreaterThan(0);
        const label = (await marks.first().textContent())!;
        expect(label).toContain(`${p.speed} m/s at ${p.angle}°`);
        const k = kernelValues(label);
        expect(Math.abs(k.speed - p.speed)).toBeLessThan(p.speedTol);
        expect(Math.abs(k.angle - p.angle)).toBeLessThan(p.angleTol);
      }
    }
    // The impact's phases on Fig. 12.
    expect(await page.locator('#fig12 rect[data-span="compression"]').count()).toBe(1);
    expect(await page.locator('#fig12 rect[data-span="restitution"]').count()).toBe(1);
    expect(await page.locator('#fig12 rect[data-span="both slip"]').count()).toBeGreaterThan(0);
    // The speed table: three tolerances and the anchors' scheme.
    await expect.poll(() => page.getByRole('table', { name: 'Speed against error' }).locator('tbody tr').count()).toBe(4);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('changing the restitution redraws Fig. 9, the rebound and the shot, and keeps the state in the URL', async () => {
    const { page, errors } = await open(env.browser, `${env.server.url}/lab`);
    const curve = page.locator('#fig9 polyline[data-series="topspin k = 1"]').first();
    const before = await curve.getAttribute('points');
    const speedBefore = await page.getByLabel('Rebound', { exact: true }).textContent();
    const hashBefore = await page.getByRole('img', { name: 'Shot preview' }).getAttribute('data-outcome-hash');
    await page.getByLabel('restitution').fill('0.5');
    await expect.poll(() => curve.getAttribute('points')).not.toBe(before);
    expect(await page.getByLabel('Rebound', { exact: true }).textContent()).not.toBe(speedBefore);
    expect(await page.getByRole('img', { name: 'Shot preview' }).getAttribute('data-outcome-hash')).not.toBe(hashBefore);
    expect(new URL(page.url()).searchParams.get('ee')).toBe('0.5');
    const ms = Number(await page.locator('section.lab').evaluate((el) => (el.parentElement as HTMLElement).dataset.redrawMs));
    expect(ms).toBeGreaterThan(0);
    console.log(`lab: a change of restitution redrew in ${ms} ms`);
    // A refused value says why and changes nothing.
    await page.getByLabel('restitution').fill('1.5');
    await expect.poll(() => page.getByRole('alert').textContent()).toMatch(/restitution/);
    expect(new URL(page.url()).searchParams.get('ee')).toBe('0.5');
    expect(errors).toEqual([]);
    await page.close();
  });

  it('a refused value (mass -1) is marked while typed, says which value the figures use, and shows it again on leaving', async () => {
    const { page, errors } = await open(env.browser, `${env.server.url}/lab`);
    const mass = page.getByLabel('mass (kg)');
    const inUse = String(PAPER.M);
    expect(await mass.inputValue()).toBe(inUse);
    const caption = await page.locator('#fig9 svg').innerHTML();
    await mass.fill('-1');
    await expect.poll(() => mass.getAttribute('aria-invalid')).toBe('true');
    expect(await page.getByRole('alert').textContent()).toBe(`mass (kg): must lie in [0.05, 0.5]; the figures use ${inUse} until a value is accepted.`);
    await mass.press('Tab');
    // The input shows the value the figures use, no longer marked, and the alert still says why.
    await expect.poll(() => mass.inputValue()).toBe(inUse);
    expect(await mass.getAttribute('aria-invalid')).toBeNull();
    expect(await page.getByRole('alert').textContent()).toBe(`mass (kg): must lie in [0.05, 0.5]; ${inUse} is still in use.`);
    expect(await page.locator('#fig9 svg').innerHTML()).toBe(caption);
    expect(new URL(page.url()).searchParams.get('M')).toBeNull();
    expect(errors).toEqual([]);
    await page.close();
  });

  it('a shared URL opens the same view', async () => {
    const { page, errors } = await open(env.browser, `${env.server.url}/lab?ee=0.7&muW=0.2&V0=1.5&alpha=30&kS=-1`);
    expect(await page.getByLabel('restitution').inputValue()).toBe('0.7');
    expect(await page.getByLabel('cushion friction').inputValue()).toBe('0.2');
    expect(await page.getByLabel('speed V0').inputValue()).toBe('1.5');
    expect(await page.locator('#fig12 svg').innerHTML()).toContain('V0 = 1.5 m/s, α = 30°, ω_S = -1 V0/R');
    const q = new URL(page.url()).searchParams;
    expect([q.get('ee'), q.get('muW'), q.get('V0'), q.get('alpha'), q.get('kS')]).toEqual(['0.7', '0.2', '1.5', '30', '-1']);
    expect(errors).toEqual([]);
    await page.close();
  });
});
