// SPDX-License-Identifier: GPL-3.0-or-later
//
// The drop-in viewer on an otherwise plain page (examples/embed.html) in headless Chromium: the
// <desia-viewer> element and the viewer mounted by mountViewer both check their file with the
// package's core and draw it (pixels on the canvas, 'ready' events), the element's API plays,
// pauses and explodes, its blocking graphs match the core's report, nothing leaves the origin,
// nothing is logged as an error, and a missing file shows its error inside the element.
//
//   node --test tests/browser/embed.test.mjs
//
// Needs the same as playground.test.mjs. Screenshots go to test-artifacts/embed-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadDesiaModule } from '../../wasm/index.js';
import { REPO_ROOT, checkPrerequisites, openBrowser, screenshot } from './support.mjs';

const NINE = 'Cube_4x4x4_K9.puz';
const SEVEN = 'Cube_4x4x4_K9_01.puz';
const READY_TIMEOUT_MS = 30_000;
/** The viewer's background (view.js): pixels far from it belong to the drawing. */
const BACKGROUND = [0x1b, 0x1e, 0x24];

/**
 * Share of an element's pixels that are clearly coloured (parts), from a screenshot decoded by
 * the browser in a blank page (so the embed page's policy and state stay untouched).
 */
async function colouredShare(context, png) {
  const probe = await context.newPage();
  try {
    return await probe.evaluate(async ({ base64, background }) => {
      const image = new Image();
      image.src = `data:image/png;base64,${base64}`;
      await image.decode();
      const canvas = document.createElement('canvas');
      canvas.width = image.width;
      canvas.height = image.height;
      const context2d = canvas.getContext('2d');
      context2d.drawImage(image, 0, 0);
      const { data } = context2d.getImageData(0, 0, canvas.width, canvas.height);
      let coloured = 0;
      for (let i = 0; i < data.length; i += 4) {
        const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
        const distance = Math.abs(r - background[0]) + Math.abs(g - background[1]) + Math.abs(b - background[2]);
        const saturation = Math.max(r, g, b) - Math.min(r, g, b);
        if (distance > 60 && saturation > 30) coloured += 1;
      }
      return coloured / (data.length / 4);
    }, { base64: png.toString('base64'), background: BACKGROUND });
  } finally {
    await probe.close();
  }
}

/** State of a viewer host (a <desia-viewer> or mountViewer's element), read through its shadow root. */
function viewerState(page, selector) {
  return page.evaluate((hostSelector) => {
    const host = document.querySelector(hostSelector);
    const root = host?.shadowRoot;
    return {
      state: host?.dataset.state ?? '',
      canvas: Boolean(root?.querySelector('canvas')),
      badge: root?.querySelector('.badge')?.hidden === false ? root.querySelector('.badge').textContent : '',
      message: root?.querySelector('.message')?.hidden === false ? root.querySelector('.message').textContent : '',
      step: Number(root?.querySelector('.viewport')?.dataset.step ?? NaN),
      exploded: root?.querySelector('.viewport')?.dataset.exploded ?? '',
      parts: root?.querySelector('.viewport')?.dataset.parts ?? '',
    };
  }, selector);
}

describe('drop-in viewer on examples/embed.html', { timeout: 90_000 }, () => {
  let browser;
  let server;
  let context;
  let page;
  let embedUrl;
  let core;
  const requestedUrls = [];
  const pageErrors = [];
  const consoleErrors = [];

  before(async () => {
    checkPrerequisites([NINE, SEVEN]);
    browser = await openBrowser();
    ({ server, context, page } = browser);
    embedUrl = new URL('/examples/embed.html', server.url).href;
    context.on('request', (request) => requestedUrls.push(request.url()));
    page.on('pageerror', (error) => pageErrors.push(error.message));
    page.on('console', (message) => {
      if (message.type() === 'error') consoleErrors.push(message.text());
    });
    // The viewers' events do not bubble: a capturing listener on window sees them all.
    await page.addInitScript(() => {
      window.__viewerEvents = [];
      for (const type of ['ready', 'error']) {
        window.addEventListener(type, (event) => {
          if (event instanceof CustomEvent) {
            window.__viewerEvents.push({ type, id: event.target.id, message: event.detail?.message ?? '' });
          }
        }, true);
      }
    });
    core = await loadDesiaModule();
  });

  after(async () => {
    await browser?.close();
  });

  it('renders both viewers: the element and the mountViewer call', async () => {
    await page.goto(embedUrl);
    await page.waitForFunction(() => ['cube-nine', 'seven-parts'].every(
      (id) => window.__viewerEvents.some((event) => event.type === 'ready' && event.id === id),
    ), null, { timeout: READY_TIMEOUT_MS }).catch(async (error) => {
      await screenshot(page, 'embed-timeout');
      throw new Error(`viewers not ready: ${JSON.stringify(await page.evaluate(() => window.__viewerEvents))}; `
        + `console errors: ${consoleErrors.join(' | ')}; ${error.message}`);
    });
    await page.evaluate(() => document.querySelector('#cube-nine').pause());
    await screenshot(page, 'embed-page');

    for (const [selector, parts] of [['#cube-nine', 9], ['#seven-parts', 7]]) {
      const state = await viewerState(page, selector);
      assert.equal(state.state, 'ready', `${selector}: ${state.message}`);
      assert.equal(state.canvas, true, `${selector}: a canvas in the viewer`);
      assert.equal(state.parts, String(parts), `${selector}: one mesh per part`);
      assert.equal(state.badge, `Interlocking · key: part 1 · ${parts} parts`);
      const png = await page.locator(selector).screenshot({ path: path.join(REPO_ROOT, `test-artifacts/embed-${selector.slice(1)}.png`) });
      const share = await colouredShare(context, png);
      assert.ok(share > 0.04, `${selector}: only ${(share * 100).toFixed(1)}% of the viewer shows parts`);
    }
    // The mounted viewer was asked for an exploded view.
    assert.equal((await viewerState(page, '#seven-parts')).exploded, '0.60');
    // The page read the report too: the caption quotes the core's reason.
    assert.match(await page.textContent('#seven-caption'), /7 parts: only the key \(part 1\) can move, along \+y\.$/);
  });

  it('plays, pauses and explodes through the element', async () => {
    const host = page.locator('#cube-nine');
    const steps = await host.evaluate((element) => element.viewer.steps);
    assert.equal(steps, 8);
    // autoplay was on; the first test paused it. Play again at a quick pace.
    await host.evaluate((element) => {
      element.viewer.setStep(0);
      element.play();
    });
    await page.waitForFunction(() => document.querySelector('#cube-nine').viewer.step > 0.3);
    assert.equal(await host.evaluate((element) => element.viewer.playing), true);
    await host.evaluate((element) => element.pause());
    const pausedAt = (await viewerState(page, '#cube-nine')).step;
    await page.waitForTimeout(400);
    assert.equal((await viewerState(page, '#cube-nine')).step, pausedAt, 'paused');
    assert.equal(await host.evaluate((element) => element.viewer.playing), false);

    await host.evaluate((element) => element.viewer.setStep(0));
    const assembled = await host.evaluate((element) => element.viewer.partPositions());
    await host.evaluate((element) => element.setAttribute('exploded', ''));
    assert.equal((await viewerState(page, '#cube-nine')).exploded, '1.00');
    const exploded = await host.evaluate((element) => element.viewer.partPositions());
    assert.notDeepEqual(exploded, assembled);
    await host.evaluate((element) => element.removeAttribute('exploded'));
    assert.deepEqual(await host.evaluate((element) => element.viewer.partPositions()), assembled);
  });

  it("draws the element's blocking graphs from the core's report", async () => {
    const report = core.check(readFileSync(path.join(REPO_ROOT, 'examples/voxel', NINE), 'utf8'), { source: NINE });
    const host = page.locator('#cube-nine');
    await host.evaluate((element) => element.shadowRoot.querySelector('.graphs-button').click());
    const figures = await host.evaluate((element) => [...element.shadowRoot.querySelectorAll('figure.dbg-graph')].map((figure) => ({
      direction: figure.dataset.direction,
      nodes: figure.querySelectorAll('circle.dbg-node').length,
      edges: figure.querySelectorAll('path.dbg-edge').length,
      components: Number(figure.dataset.components),
      key: [...figure.querySelectorAll('circle.dbg-node[data-key="true"]')].map((node) => node.dataset.part),
    })));
    await host.screenshot({ path: path.join(REPO_ROOT, 'test-artifacts/embed-graphs.png') });
    assert.deepEqual(figures, report.graphs.map((graph) => ({
      direction: graph.direction, nodes: 9, edges: graph.edges.length, components: graph.components.length, key: ['1'],
    })));
    await host.evaluate((element) => element.shadowRoot.querySelector('.graphs-button').click());
  });

  it('keeps its styles to itself and asks nothing from other origins', async () => {
    // The page's paragraphs keep the page's serif font: the viewer's styles live in its shadow root.
    const font = await page.evaluate(() => getComputedStyle(document.querySelector('p')).fontFamily);
    assert.match(font, /Georgia/);
    const external = requestedUrls.filter((url) => {
      const { protocol, hostname } = new URL(url);
      return !['data:', 'blob:'].includes(protocol) && hostname !== '127.0.0.1';
    });
    assert.deepEqual(external, [], 'requests left the origin');
    // The light module (voxels) or the full one (plates, frames): docs/architecture.md.
    assert.ok(requestedUrls.some((url) => /\/dist\/desia_(light|wasm)\.wasm$/.test(url)), 'the core was loaded');
    assert.deepEqual(consoleErrors, [], 'console errors');
    assert.deepEqual(pageErrors, [], 'page errors');
  });

  it('shows an error inside the element for a missing file', async () => {
    await page.evaluate(() => {
      const viewer = document.createElement('desia-viewer');
      viewer.id = 'missing';
      viewer.setAttribute('src', 'missing.puz');
      document.body.append(viewer);
    });
    await page.waitForFunction(() => document.querySelector('#missing').dataset.state === 'error', null, { timeout: READY_TIMEOUT_MS });
    const state = await viewerState(page, '#missing');
    await page.locator('#missing').screenshot({ path: path.join(REPO_ROOT, 'test-artifacts/embed-missing.png') });
    assert.equal(state.message, 'missing.puz: cannot fetch /examples/missing.puz (HTTP 404)');
    const events = await page.evaluate(() => window.__viewerEvents.filter((event) => event.id === 'missing'));
    assert.deepEqual(events, [{ type: 'error', id: 'missing', message: state.message }]);
    // The broken viewer leaves the others alone.
    assert.equal((await viewerState(page, '#cube-nine')).state, 'ready');
  });

  it("shows the core's message for a malformed file", async () => {
    await page.route('**/examples/broken.puz', (route) => route.fulfill({ status: 200, contentType: 'text/plain', body: '4 4 4\n1 2 3\n' }));
    await page.evaluate(() => { document.querySelector('#missing').src = 'broken.puz'; });
    await page.waitForFunction(() => /^broken\.puz:/.test(document.querySelector('#missing').shadowRoot.querySelector('.message').textContent));
    const state = await viewerState(page, '#missing');
    assert.equal(state.state, 'error');
    assert.match(state.message, /^broken\.puz:\d+/, `the core names file and line: ${state.message}`);
  });
});
