// The page of `koppel view` in headless Debian Chromium (driven by playwright-core): for a
// slider-crank (seed 000), the six-link proportional linkage with three sliders (seed 001) and
// the crank-rocker with a coupler curve (seed 003): the page is small, makes no network request,
// logs no error, the animation moves the drawn mechanism, the screenshot is not blank, and the
// input slider moves the charts' cursors to the input it shows; every chart's plot area is at
// least 240 px tall. For tests/data/hostile-names.yaml (names and a title holding markup): no
// script of the names runs, the page's own scripts do (it animates, its readout shows the names
// as text).
//
// usage: node page_test.mjs KOPPEL NODE_MODULES_DIR CHROMIUM CATALOG_DIR
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { checker, launch, watch, checkQuiet, inkOf, hostile, watchDialogs, checkNoScriptRan } from '../page_harness.mjs';

const [koppel, npmDir, chromium, catalog] = process.argv.slice(2);
const require = createRequire(path.resolve(npmDir, 'package.json'));
const { chromium: browserType } = require('playwright-core');
const { PNG } = require('pngjs');

// The size the issue allows for a seed mechanism's page.
const kMaxPageBytes = 300 * 1024;
const { check, finish } = checker();

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'koppel-view-'));
const context = await launch(browserType, chromium, work, fs, path, { viewport: { width: 1250, height: 1000 } });

try {
  for (const [id, link] of [['slider-crank-offset', 'crank'], ['proportional-linkage', 'slot'], ['mzc-crank-rocker', 'coupler']]) {
    const html = path.join(work, id + '.html');
    execFileSync(koppel, ['view', path.join(catalog, id + '.yaml'), '-o', html]);
    const bytes = fs.statSync(html).size;
    console.log(`${id}: page ${(bytes / 1024).toFixed(1)} KB`);
    check(bytes < kMaxPageBytes, `${id}: page of ${bytes} bytes exceeds ${kMaxPageBytes}`);

    const page = await context.newPage();
    const watched = await watch(page);
    await page.goto('file://' + html);
    await page.waitForSelector(`svg.scheme g.link[data-link="${link}"]`, { state: 'attached' });

    // the animation advances: the moving link's transform changes between two frames
    const transform = () => page.getAttribute(`svg.scheme g.link[data-link="${link}"]`, 'transform');
    const first = await transform();
    await page.waitForTimeout(400);
    const second = await transform();
    check(first !== second, `${id}: the ${link} did not move between two frames (${first})`);

    // the screenshot is not blank: many pixels that are not the background, in several colours
    const { share, colours } = inkOf(PNG.sync.read(await page.screenshot()), 240);
    check(share > 0.02 && colours > 20, `${id}: screenshot looks blank (${(100 * share).toFixed(2)} % ink, ${colours} colours)`);

    // issue 22 item 15: the charts' plot areas were about 100 px tall; at least 240 px
    const kMinPlotHeight = 240;
    const heights = await page.evaluate(() =>
      Array.from(document.querySelectorAll('.chart .u-over')).map((o) => o.getBoundingClientRect().height));
    check(heights.length > 0, `${id}: no chart on the page`);
    for (const h of heights) check(h >= kMinPlotHeight, `${id}: a chart's plot area is ${h} px tall, less than ${kMinPlotHeight}`);

    // moving the slider moves the cursor to the input it shows
    await page.click('#play');  // pause
    const positions = [];
    for (const index of [30, 200]) {
      await page.$eval('#input-slider', (el, v) => { el.value = String(v); el.dispatchEvent(new Event('input')); }, index);
      const state = await page.evaluate(() => {
        const cursor = document.querySelector('.koppel-cursor');
        const over = cursor.parentElement.getBoundingClientRect();
        return { left: parseFloat(cursor.style.left), width: over.width, text: document.getElementById('input-value').textContent,
                 transform: document.querySelector('svg.scheme g.link').getAttribute('transform') };
      });
      const data = JSON.parse(await page.textContent('#koppel-data'));
      const x = data.inputs[index], lo = data.inputs[0], hi = data.inputs[data.inputs.length - 1];
      check(state.text.includes(Number(x).toPrecision(6)), `${id}: slider at ${index} shows '${state.text}', expected input ${x}`);
      // uPlot's x scale spans the data: the cursor sits at (x - lo)/(hi - lo) of the plot width
      check(Math.abs(state.left - (x - lo) / (hi - lo) * state.width) < 1.5,
        `${id}: cursor at ${state.left} px, expected ${((x - lo) / (hi - lo) * state.width).toFixed(1)} px`);
      positions.push(state);
    }
    check(positions[1].left > positions[0].left + 50, `${id}: the cursor did not follow the slider`);
    check(positions[0].transform !== positions[1].transform, `${id}: the scheme did not follow the slider`);
    // paused: no further motion
    const paused = await transform();
    await page.waitForTimeout(300);
    check(paused === await transform(), `${id}: the mechanism moved while paused`);

    checkQuiet(check, id, watched);
    await page.close();
  }

  // the repros: an output named s<img onerror=...> ran its handler on every animation
  // frame (the readout was built as HTML); a title with <!--<script> hid the page's scripts
  {
    const id = 'hostile-names';
    const html = path.join(work, id + '.html');
    execFileSync(koppel, ['view', hostile.file, '-o', html]);
    const page = await context.newPage();
    const watched = await watch(page);
    const dialogs = watchDialogs(page);
    await page.goto('file://' + html);
    await page.waitForSelector('#readout td', { state: 'attached' });
    await checkNoScriptRan(check, id, page, dialogs, hostile.title);
    const cells = await page.$$eval('#readout tr td:first-child', (tds) => tds.map((td) => td.textContent));
    check(cells[0] === hostile.drive + ' [deg]', `${id}: the readout's first name is '${cells[0]}'`);
    for (const name of [hostile.s, hostile.mu, hostile.k + '_x'])
      check(cells.some((c) => c.startsWith(name)), `${id}: the readout lacks '${name}': ${cells.join(' | ')}`);
    check(await page.textContent('#title') === hostile.title, `${id}: the heading is '${await page.textContent('#title')}'`);
    const transform = () => page.getAttribute('svg.scheme g.link[data-link^="coupler"]', 'transform');
    const first = await transform();
    await page.waitForTimeout(300);
    check(first !== await transform(), `${id}: the page does not animate`);
    checkQuiet(check, id, watched);
    await page.close();
  }
} finally {
  await context.close();
  fs.rmSync(work, { recursive: true, force: true });
}
finish();
