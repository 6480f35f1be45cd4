// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Step by step panel in headless Chromium, at 1400x900 and at 390x844 (issue 11, item 8):
// the camera is framed once when the session starts and then stays where the user put it for
// every preview, choice, step back and finish; the new part is highlighted and the remainder
// ghosted; the ranked children appear side by side as pictures that preview on a click; "Finish
// automatically from here" runs the designer's search below the session's node in the worker and
// shows the verified puzzle.
//
//   node --test tests/browser/step-by-step.test.mjs
//
// Screenshots go to test-artifacts/step-by-step-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import { assertInterlockingWithKey, checkPrerequisites, openBrowser, pageState, screenshot, showDesignSettings, waitForReady } from './support.mjs';

const CUBE_SHAPE = 'Cube_4x4x4_origin.puz';

async function camera(page) {
  return page.evaluate(() => {
    const { camera: position, target } = window.__desiaView.framing();
    return { position, target };
  });
}

async function stepState(page) {
  return {
    ...(await pageState(page)),
    ...(await page.evaluate(() => ({
      outcome: document.body.dataset.design ?? '',
      message: document.querySelector('#design-message').textContent,
      session: document.querySelector('#session-state').textContent,
      highlight: document.querySelector('#viewport').dataset.highlight ?? '',
      ghost: document.querySelector('#viewport').dataset.ghost ?? '',
      thumbnails: Number(document.querySelector('#session-children').dataset.count ?? 0),
    }))),
  };
}

/** Clicks and waits until the worker has answered and the page shows the result. */
async function act(page, selector) {
  await page.click(selector);
  await page.waitForFunction(() => document.body.dataset.design !== 'running' && document.body.dataset.status === 'ready', null, { timeout: 60_000 });
  return stepState(page);
}

/** Turns the view a little, as a user dragging on it would. */
async function orbit(page) {
  const canvas = page.locator('#viewport canvas');
  await canvas.scrollIntoViewIfNeeded();
  const box = await canvas.boundingBox();
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 60, y + 20, { steps: 5 });
  await page.mouse.up();
}

for (const viewport of [{ width: 1400, height: 900 }, { width: 390, height: 844 }]) {
  const size = `${viewport.width}x${viewport.height}`;
  describe(`step by step at ${size}`, { timeout: 120_000 }, () => {
    let browser;
    let page;
    const pageErrors = [];

    before(async () => {
      checkPrerequisites([CUBE_SHAPE]);
      browser = await openBrowser({ viewport });
      page = browser.page;
      page.on('pageerror', (error) => pageErrors.push(error.message));
    });

    after(async () => {
      await browser?.close();
    });

    it('keeps the camera, highlights the new part, shows the children side by side and finishes from here', async () => {
      await page.goto(`${browser.server.url}?example=${CUBE_SHAPE}&parts=9&seed=3`);
      await showDesignSettings(page); // folded on a phone
      await waitForReady(page, CUBE_SHAPE);
      await page.click('#session-details summary');
      let state = await act(page, '#session-start');
      assert.match(state.session, /^1 of 9 parts/);
      // Pictures of the first ranked children, made lazily after the node is shown.
      await page.waitForFunction(() => Number(document.querySelector('#session-children').dataset.count) > 0);
      assert.equal((await stepState(page)).thumbnails, 6);
      assert.equal(await page.locator('#session-children img').count(), 6, 'every child has its picture (WebGL works)');

      // The user turns the view; from now on nothing re-frames it.
      await orbit(page);
      const kept = await camera(page);

      await page.locator('#session-children .child-thumbnail[data-index="2"]').click();
      await page.waitForFunction(() => document.body.dataset.source?.endsWith('_child2.json') && document.body.dataset.status === 'ready');
      state = await stepState(page);
      assert.equal(state.meshes, '2');
      assert.deepEqual([state.highlight, state.ghost], ['1', '2'], 'the new part glows, the remainder is ghosted');
      assert.deepEqual(await camera(page), kept, 'a preview keeps the camera');
      assert.equal(await page.getAttribute('#session-children .child-thumbnail[data-index="2"]', 'aria-pressed'), 'true');
      await screenshot(page, `step-by-step-preview-${size}`);

      for (const child of [1, 2]) {
        await page.fill('#session-child', String(child));
        state = await act(page, '#session-choose');
        assert.deepEqual(await camera(page), kept, `choosing child ${child} keeps the camera`);
      }
      assert.match(state.session, /^3 of 9 parts/);
      assert.deepEqual([state.highlight, state.ghost], ['2', '3']);
      state = await act(page, '#session-back');
      assert.match(state.session, /^2 of 9 parts/);
      assert.deepEqual(await camera(page), kept, 'going back keeps the camera');
      await page.fill('#session-child', '2');
      state = await act(page, '#session-choose');
      await page.waitForFunction(() => Number(document.querySelector('#session-children').dataset.count) > 0);
      await screenshot(page, `step-by-step-step-${size}`);

      // Finish automatically from here: the designer's search below this node, verified.
      state = await act(page, '#session-finish');
      assert.equal(state.outcome, 'success', state.message);
      assert.match(state.message, /^designed and verified a 9-part interlocking puzzle/);
      assert.equal(state.source, 'Cube_4x4x4_N9_seed3_from_step3.puz');
      assertInterlockingWithKey(state, 1);
      assert.equal(state.parts, '9');
      assert.equal(state.highlight, '', 'a finished puzzle has no remainder');
      assert.deepEqual(await camera(page), kept, 'the finished puzzle is seen from the same place');
      assert.match(state.session, /^3 of 9 parts/, 'the session stays where it was');
      await screenshot(page, `step-by-step-finished-${size}`);
      assert.deepEqual(pageErrors, []);
    });
  });
}
