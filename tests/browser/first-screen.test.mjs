// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 28, the playground's first visit, in headless Chromium at 1400x900 and 390x844: a first
// screen that says what desia is and offers three steps, a default example Design makes sense on,
// plain toolbar words (item 3); on a phone the verdict and errors directly under the view, the
// Design settings folded, tap targets of at least 44 px (item 1); the camera framed to the
// assembly, widened only when the disassembly is played, double-click frames again (item 2);
// unfinished inputs said neutrally (item 5); exports of what is not verified only with a visible
// warning, greyed formats with a visible reason, a default sheet that fits a laser bed (item 4);
// long lists folded (item 6); the key named one way (item 7); the small items of item 9 that the
// page can fix (difficulty before Design, .fpuz greyed for a curved frame, a toolbar that does not
// jump, the sheet preview's message above the sheets and without CSP errors). Screenshots:
// test-artifacts/first-screen-*.png.

import { after, before, describe, it } from 'node:test';
import assert from 'node:assert/strict';
import {
  checkPrerequisites, openBrowser, pageState, screenshot, showDesignSettings, waitForReady, waitForSettled,
} from './support.mjs';

const DEFAULT_EXAMPLE = 'Cube_4x4x4_origin.puz';
const SCAFFOLD_RESULT = 'scaffold_92_result.json';
const DESIGN_TIMEOUT_MS = 60_000;
/** A finger's size (WCAG 2.5.5); the issue counted 48 phone controls under 32 px. */
const TAP_PX = 44;
/** A finished result fills at least this share of the view's width (it was 10-20 %). */
const MIN_FILL = 0.45;

async function framing(page) {
  return page.evaluate(() => window.__desiaView.framing());
}

/** Clicks Design and waits for its outcome. */
async function design(page) {
  await page.click('#design-button');
  await page.waitForFunction(() => document.body.dataset.design !== 'running', null, { timeout: DESIGN_TIMEOUT_MS });
  return page.evaluate(() => ({
    outcome: document.body.dataset.design ?? '',
    message: document.querySelector('#design-message').textContent,
  }));
}

for (const viewport of [{ width: 1400, height: 900 }, { width: 390, height: 844 }]) {
  const size = viewport.width;
  const phone = size < 760;

  describe(`first visit at ${size}x${viewport.height}`, { timeout: 240_000 }, () => {
    let browser;
    let server;
    let page;
    const pageErrors = [];
    const consoleErrors = [];

    before(async () => {
      checkPrerequisites([DEFAULT_EXAMPLE]);
      browser = await openBrowser({ viewport });
      ({ server, page } = browser);
      page.on('pageerror', (error) => pageErrors.push(error.message));
      page.on('console', (message) => { if (message.type() === 'error') consoleErrors.push(message.text()); });
    });

    after(async () => {
      await browser?.close();
    });

    it('says what desia is, offers three steps and opens a shape to design (item 3)', async () => {
      await page.goto(server.url);
      const state = await waitForReady(page, DEFAULT_EXAMPLE);
      await screenshot(page, `first-screen-start-${size}`);
      assert.equal(state.verdictCode, 'shape', `the default example is a shape to design from: ${state.verdict}`);
      const intro = await page.evaluate(() => {
        const box = document.querySelector('#intro').getBoundingClientRect();
        return {
          top: box.top, bottom: box.bottom, text: document.querySelector('#intro').textContent.replace(/\s+/g, ' '),
          steps: [...document.querySelectorAll('#intro .intro-step')].map((step) => ({
            text: step.textContent.replace(/\s+/g, ' ').trim(), visible: step.getBoundingClientRect().width > 0,
          })),
          next: document.querySelector('#intro').dataset.next,
        };
      });
      assert.ok(intro.bottom <= viewport.height / 2, `the introduction is on the first screen: ${JSON.stringify(intro)}`);
      assert.match(intro.text, /designs and checks interlocking assemblies/);
      assert.deepEqual(intro.steps.map((step) => step.text), ['1 Pick an example', '2 Design', '3 Play / export']);
      assert.ok(intro.steps.every((step) => step.visible), 'the three steps are visible');
      assert.equal(intro.next, 'design', 'a shape: Design is the next step');
      if (!phone) {
        // Below 1400 px too (the tagline used to be hidden there): the steps are visible, and the
        // toolbar fits (nothing cut off at its right end).
        await page.setViewportSize({ width: 1000, height: 800 });
        const narrow = await page.evaluate(() => ({
          steps: [...document.querySelectorAll('#intro .intro-step')].map((step) => step.getBoundingClientRect().toJSON()),
          toolbar: { scroll: document.querySelector('.toolbar').scrollWidth, client: document.querySelector('.toolbar').clientWidth },
          status: document.querySelector('.toolbar-status').getBoundingClientRect().right,
        }));
        await page.waitForTimeout(200); // the view's ResizeObserver
        const fill = await framing(page);
        await screenshot(page, 'first-screen-start-1000');
        if (fill.distance > 0) {
          // The narrower view moved the camera back: the shape still fits (it overflowed before).
          assert.ok(fill.fillWidth > 0.3 && fill.fillWidth < 0.95, `the shape fills ${fill.fillWidth} of the narrower view`);
        }
        assert.ok(narrow.steps.every((box) => box.width > 0 && box.bottom < 200), `steps at 1000 px: ${JSON.stringify(narrow.steps)}`);
        assert.ok(narrow.toolbar.scroll <= narrow.toolbar.client && narrow.status <= 1000, `toolbar at 1000 px: ${JSON.stringify(narrow)}`);
        await page.setViewportSize(viewport);
      }
      // Plain toolbar words: no "Test: graphs (DBG)" jargon alone.
      const method = await page.evaluate(() => document.querySelector('#method-select').selectedOptions[0].textContent);
      assert.equal(method, 'blocking graphs (fast)');
      assert.equal(await page.evaluate(() => [...document.querySelectorAll('.toolbar .field > span')].map((span) => span.textContent).includes('Test')), false);
      // The difficulty of the request is said before Design is pressed (item 9).
      assert.equal(await page.isVisible('#design-difficulty'), true);
      assert.match(await page.textContent('#design-difficulty'), /^N = 7: ~9\.1 voxels per part: usually succeeds$/);
      // Step 2 goes to the Design button.
      await page.click('#intro li[data-step="design"] .intro-step');
      assert.equal(await page.evaluate(() => document.activeElement.id), 'design-button');
    });

    it('keeps the verdict and errors under the view on a phone, the settings folded, tap targets of 44 px (item 1)', async () => {
      await page.evaluate(() => window.scrollTo(0, 0));
      const layout = await page.evaluate(() => {
        const box = (css) => document.querySelector(css).getBoundingClientRect();
        return {
          viewBottom: box('.viewer').bottom, verdictTop: box('#verdict').top, verdictBottom: box('#verdict').bottom,
          settingsOpen: document.querySelector('#design-settings').open, designTop: box('#design-panel').top,
        };
      });
      if (phone) {
        assert.ok(layout.verdictTop >= layout.viewBottom - 1 && layout.verdictTop - layout.viewBottom < 60,
          `the verdict directly under the view: ${JSON.stringify(layout)}`);
        assert.ok(layout.verdictBottom <= viewport.height, `the verdict above the fold (it was at y≈1255): ${JSON.stringify(layout)}`);
        assert.ok(layout.designTop > layout.verdictBottom, 'Design comes after the verdict');
        assert.equal(layout.settingsOpen, false, 'the Design settings are folded');
        // Tap targets: every control of the toolbar, the introduction, the playback bar and Design.
        const small = await page.evaluate((minimum) => [...document.querySelectorAll(
          '.toolbar button, .toolbar select, .toolbar .file-button, .toolbar a, .intro button, #viewer-controls button, '
          + '#viewer-controls select, #viewer-controls input[type="range"], #viewer-controls .inline-control, '
          + '#design-panel .form-buttons button, #design-settings > summary, #session-details > summary',
        )].filter((node) => node.getClientRects().length > 0).map((node) => {
          const box = node.getBoundingClientRect();
          return { id: node.id || node.className || node.tagName, width: Math.round(box.width), height: Math.round(box.height) };
        }).filter((box) => box.width < minimum || box.height < minimum), TAP_PX);
        assert.deepEqual(small, [], `controls under ${TAP_PX} px`);
        const loop = await page.locator('#disassembly-loop').evaluate((box) => box.closest('label').getBoundingClientRect().height);
        assert.ok(loop >= TAP_PX, `Loop is ${loop} px tall (it was 13)`);
        // Every control of the page, with every section unfolded (the issue counted 48 under 32 px).
        const folded = await page.evaluate(() => [...document.querySelectorAll('details:not([open])')].map((details) => {
          details.open = true;
          return details.id;
        }));
        const everywhere = await page.evaluate((minimum) => [...document.querySelectorAll('button, select, input, summary, a, .part-item')]
          .filter((node) => node.getClientRects().length > 0 && node.type !== 'file'
            && !(node.type === 'checkbox' && node.closest('label')?.getBoundingClientRect().height >= minimum))
          .map((node) => {
            const box = node.getBoundingClientRect();
            return { id: node.id || node.className || node.tagName, width: Math.round(box.width), height: Math.round(box.height) };
          }).filter((box) => box.width < minimum || box.height < minimum), TAP_PX);
        assert.deepEqual(everywhere, [], `controls under ${TAP_PX} px anywhere on the page`);
        await page.evaluate((ids) => { for (const id of ids) if (id) document.getElementById(id).open = false; }, folded);
      } else {
        assert.equal(layout.settingsOpen, true, 'wide screens show the settings');
      }
      // A bad file: its message where the verdict is, above the fold.
      await page.setInputFiles('#file-input', { name: 'bad.puz', mimeType: 'text/plain', buffer: Buffer.from('4 4 4\n1 2 3\n') });
      const failed = await waitForSettled(page, 'bad.puz');
      assert.equal(failed.status, 'error');
      await page.evaluate(() => window.scrollTo(0, 0));
      const error = await page.evaluate(() => document.querySelector('#error').getBoundingClientRect().toJSON());
      await screenshot(page, `first-screen-error-${size}`);
      assert.ok(error.top > 0 && error.bottom <= viewport.height, `the error is on the first screen: ${JSON.stringify(error)}`);
      if (phone) await page.screenshot({ path: `test-artifacts/first-screen-phone-${size}-full.png`, fullPage: true });
    });

    it('frames a finished result to fill the view; playing widens it, double-click frames again (item 2)', async () => {
      await page.selectOption('#example-select', SCAFFOLD_RESULT);
      const state = await waitForReady(page, SCAFFOLD_RESULT);
      if (state.webgl !== 'on') return;
      const first = await framing(page);
      await page.evaluate(() => window.scrollTo(0, 0));
      await screenshot(page, `first-screen-scaffold-${size}`);
      assert.equal(first.widened, false);
      assert.ok(first.fillWidth >= MIN_FILL || first.fillHeight >= MIN_FILL,
        `SCAFFOLD 92 fills ${Math.round(first.fillWidth * 100)} % of the width, ${Math.round(first.fillHeight * 100)} % of the height`);
      await page.click('#disassembly-next');
      await page.waitForFunction(() => window.__desiaView.step >= 1);
      const played = await framing(page);
      assert.equal(played.widened, true, 'the tray and paths widen the framing once played');
      assert.ok(played.distance > first.distance, `wider: ${played.distance} > ${first.distance}`);
      await page.locator('#disassembly-range').fill('0');
      await page.locator('#viewport canvas').dblclick();
      const again = await framing(page);
      assert.equal(again.widened, false, 'double-click frames the assembly again');
      assert.ok(Math.abs(again.distance - first.distance) < first.distance * 0.01, `${again.distance} vs ${first.distance}`);
    });

    it('says unfinished inputs neutrally, names the key one way and folds long lists (items 5, 6, 7)', async () => {
      for (const [file, text] of [['table.json', 'Plate structure: 6 plates, ready to design joints'], ['frame_cube.json', 'Frame: 12 beams, ready to design joints']]) {
        await page.selectOption('#example-select', file);
        const state = await waitForReady(page, file);
        assert.equal(state.verdictCode, 'input', `${file}: ${state.verdict}`);
        assert.equal(state.verdict, text);
        const colour = await page.evaluate(() => getComputedStyle(document.querySelector('#verdict')).color);
        assert.notEqual(colour, 'rgb(255, 122, 107)', 'not the red of a failed puzzle');
      }
      await screenshot(page, `first-screen-frame-input-${size}`);
      // A frame result: its key is a beam in the verdict, the Key line and the part list.
      await page.selectOption('#example-select', 'frame_cube_result.json');
      const frame = await waitForReady(page, 'frame_cube_result.json');
      assert.equal(frame.verdict, 'Interlocking, key: beam 1');
      assert.equal(await page.textContent('#key'), 'beam 1');
      assert.match(await page.textContent('#part-list [data-part="1"]'), /^beam 1 \(key\)/);
      // The DODECAHEDRON's 31 base directions and 31 graphs are folded behind their counts.
      await page.selectOption('#example-select', 'dodecahedron.json');
      await waitForReady(page, 'dodecahedron.json');
      const folded = await page.evaluate(() => ({
        summary: document.querySelector('#base-directions summary')?.textContent ?? '',
        open: document.querySelector('#base-directions details')?.open,
        graphs: document.querySelector('#graphs-summary').textContent,
        graphsOpen: document.querySelector('#graphs-details').open,
        height: document.querySelector('#base-directions').getBoundingClientRect().height,
      }));
      assert.match(folded.summary, /^31 directions: \+x, \+y, \+z, … \(show all\)$/);
      assert.equal(folded.open, false);
      assert.equal(folded.graphs, 'Blocking graphs (31)');
      assert.equal(folded.graphsOpen, false, '31 graphs start folded');
      assert.ok(folded.height < 60, `the folded list is ${folded.height} px tall`);
    });

    it('shows a design step short of its target as in progress (item 5)', async () => {
      await page.selectOption('#example-select', DEFAULT_EXAMPLE);
      await waitForReady(page, DEFAULT_EXAMPLE);
      await page.click('#session-details summary');
      await page.click('#session-start');
      await page.waitForFunction(() => document.body.dataset.design !== 'running' && document.body.dataset.status === 'ready'
        && /of \d+ parts/.test(document.querySelector('#session-state').textContent));
      await page.click('#session-next');
      await page.waitForFunction(() => document.body.dataset.design !== 'running' && document.body.dataset.status === 'ready'
        && /^2 of/.test(document.querySelector('#session-state').textContent));
      const state = await pageState(page);
      assert.equal(state.verdictCode, 'in-progress', state.verdict);
      assert.match(state.verdict, /^Design in progress: 2 of 7 parts placed$/);
      assert.doesNotMatch(await page.textContent('#reason'), /needs at least three parts/);
      await screenshot(page, `first-screen-step-${size}`);
      await page.click('#session-close');
    });

    it('exports what is not verified only with a visible warning; greyed formats say why (items 4, 9)', async () => {
      // The CABINET with joints "cut": Design finds no plan; its cut sheets are bare boards.
      await page.selectOption('#example-select', 'cabinet.json');
      await waitForReady(page, 'cabinet.json');
      await showDesignSettings(page);
      await page.selectOption('#design-joints', 'cut');
      const outcome = await design(page);
      assert.equal(outcome.outcome, 'not-found', outcome.message);
      await page.selectOption('#export-format', 'svg');
      const warning = page.locator('#export-warning');
      assert.equal(await warning.isVisible(), true, 'a visible warning');
      assert.match(await warning.textContent(), /^Not jointed, not verified: cabinet\.json has no joints/);
      assert.equal(await page.inputValue('#export-sheet'), '1300x900', 'a sheet that fits a large laser bed');
      assert.equal(await page.isVisible('#export-sheet-note'), true);
      assert.match(await page.textContent('#export-sheet-note'), /1300 × 900 mm by default, a\s+large laser bed/);
      const cspBefore = consoleErrors.filter((text) => /Content Security Policy/i.test(text)).length;
      await page.click('#export-preview');
      await page.waitForFunction(() => document.querySelector('#export-panel').dataset.state === 'done');
      const preview = await page.evaluate(() => ({
        message: document.querySelector('#export-message').textContent,
        messageBottom: document.querySelector('#export-message').getBoundingClientRect().bottom,
        sheetTop: document.querySelector('#sheet-preview').getBoundingClientRect().top,
        sheets: Number(document.querySelector('#sheet-preview').dataset.sheets),
        caption: document.querySelector('#sheet-preview figcaption').textContent,
      }));
      assert.match(preview.message, /^\d+ sheets? shown below\. Not jointed or verified: see the warning above\.$/);
      assert.ok(preview.messageBottom <= preview.sheetTop, `"shown below" sits above the sheets: ${JSON.stringify(preview)}`);
      assert.match(preview.caption, /1300 × 900 mm/);
      await page.waitForTimeout(200);
      const csp = consoleErrors.filter((text) => /Content Security Policy/i.test(text));
      assert.equal(csp.length, cspBefore, `no CSP errors from previewed sheets: ${csp.join(' | ')}`);
      await page.locator('#export-panel').scrollIntoViewIfNeeded();
      await screenshot(page, `first-screen-export-warning-${size}`);

      // The paper's plan alone (Joints: planned): verified, but no joint is in the plates.
      await page.selectOption('#example-select', 'table.json');
      await waitForReady(page, 'table.json');
      await page.selectOption('#design-joints', 'planned');
      const planned = await design(page);
      assert.equal(planned.outcome, 'success', planned.message);
      await page.waitForFunction(() => document.body.dataset.status === 'ready');
      await page.selectOption('#export-format', 'svg');
      assert.equal(await page.isVisible('#export-warning'), true);
      assert.match(await page.textContent('#export-warning'), /^Joints planned, not cut: table_plan_seed1\.json says which joint goes where/);

      // A milled result: SVG and DXF greyed, the reason in the panel, not only in a tooltip.
      await page.selectOption('#example-select', 'mitred_box.json');
      await waitForReady(page, 'mitred_box.json');
      const milled = await design(page);
      assert.equal(milled.outcome, 'success', milled.message);
      await page.waitForFunction(() => document.body.dataset.status === 'ready');
      assert.equal(await page.isDisabled('#export-format option[value="svg"]'), true);
      assert.equal(await page.isVisible('#export-unavailable'), true);
      assert.match(await page.textContent('#export-unavailable'), /SVG and DXF cut sheets are greyed out: milled joints/);
      assert.equal(await page.isVisible('#export-warning'), false, 'a verified result: no warning');

      // A curved frame: .fpuz greyed with the core's reason.
      await page.selectOption('#example-select', 'flower_result.json');
      await waitForReady(page, 'flower_result.json');
      await page.waitForFunction(() => document.querySelector('#export-format option[value="fpuz"]').disabled);
      assert.match(await page.textContent('#export-unavailable'), /^\.fpuz is greyed out: beam \d+ is curved, and \.fpuz holds straight beams only/);
      assert.equal(await page.isDisabled('#export-format option[value="csv"]'), false, 'its cut list is offered');
      await page.locator('#export-panel').scrollIntoViewIfNeeded();
      await screenshot(page, `first-screen-export-fpuz-${size}`);
    });

    it('keeps the toolbar still when the offline badge appears (item 9)', async () => {
      if (phone) return; // one column: the badge has its own line in the status box there too
      const fresh = await browser.context.newPage();
      try {
        await fresh.goto(`${server.url}?example=${DEFAULT_EXAMPLE}`);
        await waitForReady(fresh, DEFAULT_EXAMPLE);
        const before_ = await fresh.evaluate(() => document.querySelector('#viewport').getBoundingClientRect().top);
        await fresh.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: 60_000 });
        const after_ = await fresh.evaluate(() => ({
          top: document.querySelector('#viewport').getBoundingClientRect().top,
          badge: document.querySelector('#offline-status').textContent,
        }));
        assert.equal(after_.top, before_, `the view stays at y=${before_} with "${after_.badge}" shown`);
      } finally {
        await fresh.close();
      }
    });

    it('throws no page errors', () => {
      assert.deepEqual(pageErrors, []);
    });
  });
}
