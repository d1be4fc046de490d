// The page of `koppel edit` in headless Debian Chromium (driven by playwright-core, as the view
// page's test): its solver is koppel's kernel compiled to WebAssembly, so its numbers are checked
// against the CLI's, the reference. For the seed mechanisms (000 slider-crank-offset,
// deadcentre-slider-crank; 001 proportional-linkage; 002 deadcentre-crank-rocker; 003
// mzc-crank-rocker) and two six-bars (watt-six-bar, stephenson-six-bar): window.koppel.sweep over
// the file's range equals `koppel analyze --format json` (same columns, same rows, every cell to
// 1e-9 relative, the same empty cells); toYaml() read back by the CLI gives the page's numbers;
// no console error, no network request. For slider-crank-offset besides: set("e", 0.3) gives the
// numbers of `koppel analyze --set e=0.3`; a change that cannot assemble (e = 5) is refused and
// says so; dragging the frame pivot A0 (through the API and with the pointer) re-solves on the
// same branch, and the CLI reads the exported YAML to the page's numbers, as for the
// crank-rocker's rocker pivot B0 dragged; the exports (YAML, SVG, PNG) download; the screenshot
// shows the scheme (ink and colours inside the scheme's box). A file that does not assemble
// (--set e=9): koppel edit exits 1, the page says so, shows no number, and a slider fixes it.
// tests/data/hostile-names.yaml (names and a title holding markup): no script of the names runs,
// the page works (its readout shows the names as text, its sweep and toYaml() agree with the CLI).
// Every revolute joint's handle is the pointer's, also under a slider block or on a guide line
// (slider-crank-offset B; whitworth A, B0, D; scotch-yoke A0, A; proportional-linkage A0, A, B0,
// D: the element under the pointer is the handle, and a drag moves it). The Watt-II of
// tests/data/watt-ii-branches.yaml keeps its first loop's psi (1e-9 deg against the CLI's) through
// four changes of its second loop, before and after a drag of the pivot D0, which moves in the
// frame only; where a change has no pose on the branch shown, the page says so and offers
// koppel's assembly. set() refuses what is not a finite number.
//
// usage: node editor_page_test.mjs KOPPEL NODE_MODULES_DIR CHROMIUM CATALOG_DIR [SCREENSHOT.png]
// (SCREENSHOT: where to write the page's screenshot, README's picture, README "The editor page").
import { createRequire } from 'node:module';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { checker, launch, watch, checkQuiet, inkOf, hostile, watchDialogs, checkNoScriptRan } from '../page_harness.mjs';

const [koppel, npmDir, chromium, catalog, screenshotOut] = process.argv.slice(2);
const require = createRequire(path.resolve(npmDir, 'package.json'));
const { chromium: browserType } = require('playwright-core');
const { PNG } = require('pngjs');

// The page solves with the kernel's dense path (no BTF in WebAssembly), the CLI with its block
// LU: the same Newton iterations to the same tolerance, rounding apart.
const kTolerance = 1e-9;
const { check, finish } = checker();

// `koppel analyze --format json` (exit 1 for a partial sweep still prints the table)
function analyze(file, extra = []) {
  const r = spawnSync(koppel, ['analyze', file, '--format', 'json', ...extra], { encoding: 'utf8', maxBuffer: 64 << 20 });
  if (r.status !== 0 && r.status !== 1) throw new Error(`koppel analyze ${file}: exit ${r.status}: ${r.stderr}`);
  return JSON.parse(r.stdout);
}

// The first difference between two tables beyond kTolerance, or '' when they agree.
function difference(page, cli) {
  if (JSON.stringify(page.columns) !== JSON.stringify(cli.columns)) return `columns ${page.columns} vs ${cli.columns}`;
  if (page.rows.length !== cli.rows.length) return `${page.rows.length} rows vs ${cli.rows.length}`;
  for (let r = 0; r < cli.rows.length; ++r) {
    for (let c = 0; c < cli.columns.length; ++c) {
      const a = page.rows[r][c], b = cli.rows[r][c];
      if ((a === null) !== (b === null)) return `row ${r} ${cli.columns[c]}: ${a} vs ${b}`;
      if (b !== null && !(Math.abs(a - b) <= kTolerance * Math.max(1, Math.abs(b)))) return `row ${r} ${cli.columns[c]}: ${a} vs ${b}`;
    }
  }
  return '';
}

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'koppel-edit-'));
const context = await launch(browserType, chromium, work, fs, path, { viewport: { width: 1250, height: 1100 }, acceptDownloads: true });

// The page of catalog entry `id` (or of the file `file`; with `extra` flags), koppel edit's exit
// code checked; the dialogs it opens in `dialogs`.
async function open(id, extra = [], exit = 0, file = path.join(catalog, id + '.yaml')) {
  const html = path.join(work, id + '.html');
  const r = spawnSync(koppel, ['edit', file, ...extra, '-o', html], { encoding: 'utf8' });
  check(r.status === exit, `koppel edit ${id} ${extra.join(' ')}: exit ${r.status}, expected ${exit}: ${r.stderr}`);
  const page = await context.newPage();
  const watched = await watch(page);
  const dialogs = watchDialogs(page);
  await page.goto('file://' + html);
  await page.evaluate(() => window.koppel.ready);
  return { page, watched, html, dialogs };
}

// The page's sweep over the CLI's range, against the CLI; then toYaml() read back by the CLI.
async function compare(page, id, cli, what) {
  const i = cli.input;
  const table = await page.evaluate(([a, b, s]) => window.koppel.sweep(a, b, s, 2), [i.from, i.to, i.step]);
  const diff = difference(table, cli);
  check(diff === '', `${id} ${what}: the page's sweep differs from koppel analyze: ${diff}`);
  const yaml = path.join(work, `${id}-${what.replace(/[^a-z0-9]+/gi, '_')}.yaml`);
  fs.writeFileSync(yaml, await page.evaluate(() => window.koppel.toYaml()));
  const back = analyze(yaml, ['--from', String(i.from), '--to', String(i.to), '--step', String(i.step)]);
  const again = difference(table, back);
  check(again === '', `${id} ${what}: koppel analyze of toYaml() differs from the page: ${again}`);
  return table;
}

try {
  const seeds = ['slider-crank-offset', 'deadcentre-slider-crank', 'proportional-linkage', 'deadcentre-crank-rocker',
                 'mzc-crank-rocker', 'watt-six-bar', 'stephenson-six-bar'];
  for (const id of seeds) {
    const { page, watched, html } = await open(id);
    const file = path.join(catalog, id + '.yaml');
    const cli = analyze(file);
    const table = await compare(page, id, cli, 'as read');
    console.log(`${id}: page ${(fs.statSync(html).size / 1024).toFixed(0)} KB, ${table.rows.length} rows x ${table.columns.length} columns compared`);

    if (id === 'watt-six-bar') {
      // psi1_a is read by the catalog card's checks alone: setting it would change nothing, and the
      // page refuses it as --set does, in the library's words
      const r = await page.evaluate(() => window.koppel.set('psi1_a', 1));
      check(!r.ok && /no formula of this file reads the parameter 'psi1_a'/.test(r.message), `${id}: set('psi1_a', 1): ${JSON.stringify(r)}`);
    }
    if (id === 'slider-crank-offset') {
      // a parameter: the file's formulas (A0 at [0, -e]) evaluated again, as --set e=0.3
      const set = await page.evaluate(() => window.koppel.set('e', 0.3));
      check(set.ok, `${id}: set("e", 0.3) failed: ${set.message}`);
      // the slider's thumb and the number box both show the value set
      const shownE = await page.evaluate(() => {
        const row = Array.from(document.querySelectorAll('#parameters tr')).find((tr) => tr.firstChild.textContent === 'e');
        return [+row.querySelector('input[type=range]').value, +row.querySelector('input[type=number]').value];
      });
      check(Math.abs(shownE[0] - 0.3) < 1e-12 && shownE[1] === 0.3, `${id}: after set("e", 0.3) the slider and box show ${shownE}`);
      await compare(page, id, analyze(file, ['--set', 'e=0.3']), 'e=0.3');
      const unknown = await page.evaluate(() => window.koppel.set('nope', 1));
      check(!unknown.ok, `${id}: set of an unknown parameter was accepted`);
      // not numbers: '' null [] set 0 and true set 1 ({ok: true}); 'x' blamed a formula
      const junk = await page.evaluate(() => ['', null, [], true, 'x', '0.3', NaN, Infinity].map((v) => window.koppel.set('e', v)));
      check(junk.every((r) => !r.ok && /expected a finite number/.test(r.message)), `${id}: a non-number was taken: ${JSON.stringify(junk)}`);
      check((await page.evaluate(() => window.koppel.parameters().find((p) => p.name === 'e').value)) === 0.3,
        `${id}: a refused non-number changed e`);

      // a change that cannot assemble (e = 5: the crank's end stays 4 or more below the slide
      // line, the coupler of 2.6 cannot reach it at any input): refused, said, and the numbers
      // stay those of the last valid mechanism. (A drag cannot fail so: the dragged point moves
      // on both its links, which fit together at the current pose by construction.)
      const refused = await page.evaluate(() => window.koppel.set('e', 5));
      check(!refused.ok && /cannot assemble/.test(refused.message), `${id}: an impossible change was not refused: ${JSON.stringify(refused)}`);
      const kept = await page.evaluate(() => window.koppel.sweep(0, 360, 1, 2));
      check(difference(kept, analyze(file, ['--set', 'e=0.3'])) === '', `${id}: the numbers changed after a refused change`);
      check((await page.evaluate(() => window.koppel.parameters().find((p) => p.name === 'e').value)) === 0.3,
        `${id}: the refused e = 5 shows as the current value`);
      const shown = await page.textContent('#message');
      check(/cannot assemble/.test(shown), `${id}: the page does not say that it cannot assemble: '${shown}'`);

      // a drag of the frame pivot A0 by 0.05: on the same branch (B stays right of A, s > 0 at
      // phi = 0 as the hint chose), and the exported YAML carries that branch to the CLI
      const before = await page.evaluate(() => window.koppel.sweep(0, 0, 1, 2).rows[0]);
      const moved = await page.evaluate(() => window.koppel.moveJoint('A0', 0.05, -0.3));
      check(moved.ok, `${id}: moving A0 failed: ${moved.message}`);
      const after = await page.evaluate(() => window.koppel.sweep(0, 0, 1, 2).rows[0]);
      const sIndex = cli.columns.indexOf('s');
      check(after[sIndex] > 0 && Math.abs(after[sIndex] - before[sIndex]) < 0.2,
        `${id}: after the drag s(0) = ${after[sIndex]} (before ${before[sIndex]}): not the same branch`);
      const dragged = path.join(work, 'dragged.yaml');
      fs.writeFileSync(dragged, await page.evaluate(() => window.koppel.toYaml()));
      const back = analyze(dragged, ['--from', '0', '--to', '360', '--step', '1']);
      const mine = await page.evaluate(() => window.koppel.sweep(0, 360, 1, 2));
      check(difference(mine, back) === '', `${id}: the dragged mechanism read back differs: ${difference(mine, back)}`);

      check(await page.evaluate(() => { document.getElementById('undo').click(); return window.koppel.state().error === false; }),
        `${id}: undo after the drag failed`);

      // the screenshot shows the scheme: links drawn, ink and colours inside its box
      check(await page.locator('#scheme g.link line, #scheme g.link polygon').count() >= 2, `${id}: no links drawn`);
      const { share, colours } = inkOf(PNG.sync.read(await page.locator('#scheme').screenshot()), 200);
      check(share > 0.01 && colours > 8, `${id}: the scheme looks blank (${(100 * share).toFixed(2)} % ink, ${colours} colours)`);
      const heights = await page.evaluate(() => Array.from(document.querySelectorAll('.chart .u-over')).map((o) => o.getBoundingClientRect().height));
      check(heights.length >= 2 && heights.every((h) => h >= 240), `${id}: charts' plot areas ${heights} (at least 240 px each)`);
      // the pointer: A0's handle dragged 12 px to the right re-solves (a user's drag)
      const box = await page.locator('#scheme circle[data-joint="A0"]').boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width / 2 + 12, box.y + box.height / 2, { steps: 3 });
      await page.mouse.up();
      const dragState = await page.evaluate(() => window.koppel.state());
      check(!dragState.error && /moved A0/.test(dragState.message), `${id}: the pointer drag of A0: '${dragState.message}'`);
      // the exports: YAML the CLI reads, an SVG, a PNG
      for (const [button, test] of [['#export-yaml', (b) => /links:/.test(b.toString())],
                                    ['#export-svg', (b) => /^<svg/.test(b.toString())],
                                    ['#export-png', (b) => b.subarray(1, 4).toString() === 'PNG']]) {
        const [download] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
        const bytes = fs.readFileSync(await download.path());
        check(bytes.length > 100 && test(bytes), `${id}: ${button} gave ${bytes.length} bytes: ${bytes.subarray(0, 40)}`);
      }
      if (screenshotOut) {
        await page.evaluate(() => { window.koppel.set('e', 0.8); });
        await page.$eval('#input-slider', (el) => { el.value = '60'; el.dispatchEvent(new Event('input')); });
        await page.screenshot({ path: screenshotOut, fullPage: true });
      }
    }
    if (id === 'mzc-crank-rocker') {
      // a four-bar has two assembly branches at every input (the rocker's psi far apart): a drag
      // of the rocker's pivot B0 by 1 % of the frame keeps psi at the current input within a
      // degree of where it was, on the branch shown, and the exported YAML keeps that branch
      const psi = cli.columns.indexOf('psi');
      const input = await page.evaluate(() => window.koppel.state().input);
      const at = async () => (await page.evaluate((x) => window.koppel.sweep(x, x, 1, 2), input)).rows[0][psi];
      const before = await at();
      const b0 = await page.evaluate(() => {
        const m = JSON.parse(document.getElementById('koppel-document').textContent).mechanism;
        const p = m.links.find((l) => l.frame).points.find((q) => q.name === 'B0');
        return [p.x, p.y];
      });
      const moved = await page.evaluate(([x, y]) => window.koppel.moveJoint('B0', x * 1.01, y), b0);
      check(moved.ok, `${id}: moving B0 failed: ${moved.message}`);
      const after = await at();
      check(Math.abs(after - before) < 1, `${id}: psi at ${input} went from ${before} to ${after} deg: another branch`);
      const yaml = path.join(work, 'rocker-dragged.yaml');
      fs.writeFileSync(yaml, await page.evaluate(() => window.koppel.toYaml()));
      const mine = await page.evaluate(() => window.koppel.sweep(0, 360, 1, 2));
      const diff = difference(mine, analyze(yaml, ['--from', '0', '--to', '360', '--step', '1']));
      check(diff === '', `${id}: the dragged four-bar read back differs: ${diff}`);
    }
    checkQuiet(check, id, watched);
    await page.close();
  }

  // every revolute joint's handle is the pointer's, also under a slider block or on a guide line
  // (B of the slider-crank lay inside its 28 x 16 px block; whitworth A, B0, D; scotch-yoke A0,
  // A; proportional-linkage A0, A, B0, D: the drag did nothing and said nothing)
  for (const [id, joints] of [['slider-crank-offset', ['B']], ['whitworth-quick-return', ['A', 'B0', 'D']],
                              ['scotch-yoke', ['A0', 'A']], ['proportional-linkage', ['A0', 'A', 'B0', 'D']]]) {
    const { page, watched } = await open(id);
    for (const joint of joints) {
      const box = await page.locator(`#scheme circle[data-joint="${joint}"]`).boundingBox();
      const x = box.x + box.width / 2, y = box.y + box.height / 2;
      const hit = await page.evaluate(([x, y]) => { const e = document.elementFromPoint(x, y); return e && e.getAttribute('data-joint'); }, [x, y]);
      check(hit === joint, `${id}: the pointer at ${joint}'s handle hits '${hit}'`);
      await page.mouse.move(x, y);
      await page.mouse.down();
      await page.mouse.move(x + 5, y + 3, { steps: 4 });
      await page.mouse.up();
      const s = await page.evaluate(() => window.koppel.state());
      check(!s.error && s.message.startsWith('moved ' + joint), `${id}: the pointer drag of ${joint}: '${s.message}'`);
      await page.evaluate(() => document.getElementById('undo').click());
    }
    checkQuiet(check, id, watched);
    await page.close();
  }

  // The Watt-II of a user report: four changes of the second loop (c3, b2) switched the first
  // loop's branch (psi changed), and after a drag of the pivot D0 mirrored it. The page now
  // assembles every change next to the pose shown: psi, which the second loop does not touch,
  // stays the file's at every input the page reaches (1e-9 deg), before and after the drag; the
  // dragged pivot moves in the frame only (the output link keeps D0 at its origin, D at c3).
  {
    const id = 'watt-ii-branches';
    const file = new URL('../../data/watt-ii-branches.yaml', import.meta.url).pathname;
    const psiOf = (table) => new Map(table.rows.map((r) => [r[0], r[table.columns.indexOf('psi')]]));
    const reference = psiOf(analyze(file));
    const sequence = async (page, what) => {
      for (const [name, value] of [['c3', 2.6], ['c3', 2.0], ['b2', 3.6], ['c3', 0.5]]) {
        const r = await page.evaluate(([n, v]) => window.koppel.set(n, v), [name, value]);
        // c3 = 0.5: the second loop does not close at the input shown (D0 stays open by 0.16);
        // koppel would assemble at phi = 60 deg from a random guess, the first loop crossed: the
        // page says so, keeps the pose shown and offers that assembly
        const kept = !r.ok && /cannot keep the branch shown/.test(r.message) && /does not assemble at/.test(r.message);
        check(r.ok || (name === 'c3' && value === 0.5 && kept), `${id} ${what}: set('${name}', ${value}): ${r.message}`);
        const rows = await page.evaluate(() => { const s = window.koppel.state(); return s.input === null ? [] : [s.input]; });
        const table = await page.evaluate(() => window.koppel.sweep(0, 360, 1, 2));
        const psi = psiOf(table);
        let worst = 0;
        for (const [x, v] of psi) if (v !== null && reference.has(x)) worst = Math.max(worst, Math.abs(v - reference.get(x)));
        check(psi.size > 0 && rows.length === 1 && worst <= 1e-9, `${id} ${what}: after ${name} = ${value} psi moved by ${worst} deg (${psi.size} rows)`);
      }
    };
    const { page, watched, dialogs } = await open(id, [], 0, file);
    await sequence(page, 'as read');
    // taking koppel's assembly is the user's choice, said as such
    check(await page.isVisible('#take-offer'), `${id}: no offer of koppel's assembly`);
    await page.click('#take-offer');
    const taken = await page.evaluate(() => window.koppel.state());
    check(!taken.error || /partial/.test(taken.message), `${id}: taking koppel's assembly: ${taken.message}`);
    check(/koppel's assembly/.test(taken.message) && /from a seeded random guess/.test(taken.message),
      `${id}: the page does not say whose assembly it shows: '${taken.message}'`);
    await page.close();
    const second = await open(id, [], 0, file);
    const moved = await second.page.evaluate(() => window.koppel.moveJoint('D0', 6.4, 0.3));
    check(moved.ok, `${id}: the drag of D0: ${moved.message}`);
    const yaml = await second.page.evaluate(() => window.koppel.toYaml());
    check(/output:[\s\S]*?D0: \[0, 0\]/.test(yaml), `${id}: the drag of D0 moved the output link's own point: ${yaml}`);
    await sequence(second.page, 'after D0 dragged');
    checkQuiet(check, id, watched);
    checkQuiet(check, id + ' dragged', second.watched);
    check(dialogs.length === 0, `${id}: dialogs opened`);
    await second.page.close();
  }

  // The export keeps what the user wrote: the Watt-II written with parameters and comments, after
  // set('c3', 2.6), is its own text with c3's value alone changed (the file's assembly still gives
  // the branch shown); its parameters stay alive (--set d1 changes the numbers) and it reads back
  // to the page's numbers. A drag of B0 (written [d1, 0]) changes d1 in the text. The compressor
  // in mm with masses and loads keeps its units, gravity and loads through set('l2', 170), and
  // `koppel forces` of the export equals `koppel forces --set l2=170` of the file.
  {
    const id = 'watt-ii-branches';
    const file = new URL('../../data/watt-ii-branches.yaml', import.meta.url).pathname;
    const original = fs.readFileSync(file, 'utf8');
    const { page, watched } = await open(id, [], 0, file);
    check(await page.evaluate(() => window.koppel.toYaml()) === original, `${id}: the export of the file as read is not its text byte for byte`);
    const set = await page.evaluate(() => window.koppel.set('c3', 2.6));
    check(set.ok, `${id}: set('c3', 2.6): ${set.message}`);
    const exported = await page.evaluate(() => window.koppel.exportYaml());
    const expected = original.replace('c3: 3.5,', 'c3: 2.6,');
    check(expected !== original && exported.text === expected && exported.sameBranch,
      `${id}: after set('c3', 2.6) the export is not the file with c3 alone changed:\n${exported.text}\n${exported.notes.join('; ')}`);
    const yaml = path.join(work, 'watt-ii-exported.yaml');
    fs.writeFileSync(yaml, exported.text);
    const plain = analyze(yaml, ['--step', '180']), moved = analyze(yaml, ['--step', '180', '--set', 'd1=3.2']);
    check(difference(plain, moved) !== '', `${id}: --set d1=3.2 on the export changes nothing: its parameters are dead`);
    await compare(page, id, analyze(yaml), 'c3 set');
    // a drag of B0 changes d1 (B0: [d1, 0]) and nothing else in the text but the assembly, if at all
    const b0 = await page.evaluate(() => window.koppel.moveJoint('B0', 3.6, 0));
    check(b0.ok && /d1 = 3\.6/.test(b0.message), `${id}: the drag of B0: ${b0.message}`);
    const dragged = await page.evaluate(() => window.koppel.exportYaml());
    check(/d1: 3\.6,/.test(dragged.text) && /B0: \[d1, 0\]/.test(dragged.text) && /^# The Watt-II/.test(dragged.text),
      `${id}: the export after the drag of B0 lost the user's text:\n${dragged.text}`);
    fs.writeFileSync(yaml, dragged.text);
    await compare(page, id, analyze(yaml), 'B0 dragged');
    checkQuiet(check, id + ' export', watched);
    await page.close();
  }
  {
    const id = 'slider-crank-loads';
    const file = new URL('../../data/slider-crank-loads.yaml', import.meta.url).pathname;
    const original = fs.readFileSync(file, 'utf8');
    const { page, watched } = await open(id, [], 0, file);
    const set = await page.evaluate(() => window.koppel.set('l2', 170));
    check(set.ok, `${id}: set('l2', 170): ${set.message}`);
    const text = await page.evaluate(() => window.koppel.toYaml());
    check(text === original.replace('l2: 160 ', 'l2: 170 '), `${id}: the export is not the file with l2 alone changed:\n${text}`);
    const yaml = path.join(work, 'loads-exported.yaml');
    fs.writeFileSync(yaml, text);
    const forces = (args) => spawnSync(koppel, ['forces', ...args, '--step', '30'], { encoding: 'utf8' });
    const exported = forces([yaml]), bySet = forces([file, '--set', 'l2=170']);
    check(exported.status === 0 && exported.stdout === bySet.stdout,
      `${id}: koppel forces of the export differs from --set l2=170: ${exported.stderr}\n${exported.stdout}\n${bySet.stdout}`);
    checkQuiet(check, id + ' export', watched);
    await page.close();
  }

  // a file that does not assemble as given (e = 9: the coupler cannot reach the slide line):
  // koppel edit writes the page and exits 1; the page says so, shows no numbers, and its sliders
  // fix it (e = 0.8: the file's own numbers)
  {
    const id = 'slider-crank-offset';
    const { page, watched } = await open(id, ['--set', 'e=9'], 1);
    const s = await page.evaluate(() => window.koppel.state());
    check(s.error && /cannot assemble/.test(s.message) && s.input === null, `${id} --set e=9: the page says '${s.message}'`);
    check(await page.locator('#readout tr').count() === 0, `${id} --set e=9: numbers shown for a mechanism that did not assemble`);
    const fixed = await page.evaluate(() => window.koppel.set('e', 0.8));
    check(fixed.ok, `${id} --set e=9, then e = 0.8: ${fixed.message}`);
    const cli = analyze(path.join(catalog, id + '.yaml'));
    await compare(page, id, cli, 'fixed by the slider');
    // an unassemblable file logs its failure on the page, not in the console
    checkQuiet(check, id + ' --set e=9', watched);
    await page.close();
  }

  // the repros: an output named s<img onerror=...> ran its handler on every frame (the
  // readout and the parameter table were built as HTML); a title with <!--<script> hid the
  // page's scripts (window.koppel.ready never came)
  {
    const id = 'hostile-names';
    const { page, watched, dialogs } = await open(id, [], 0, hostile.file);
    await checkNoScriptRan(check, id, page, dialogs, hostile.title);
    const cells = await page.$$eval('#readout tr td:first-child', (tds) => tds.map((td) => td.textContent));
    for (const name of [hostile.s, hostile.mu, hostile.k + '_x'])
      check(cells.includes(name), `${id}: the readout lacks '${name}': ${cells.join(' | ')}`);
    check(await page.textContent('#title') === hostile.fileTitle, `${id}: the heading is '${await page.textContent('#title')}'`);
    // the page's numbers and its YAML (names quoted for YAML) against the CLI
    const cli = analyze(hostile.file);
    check(cli.columns[0] === hostile.drive, `${id}: koppel analyze's first column is '${cli.columns[0]}'`);
    await compare(page, id, cli, 'as read');
    checkQuiet(check, id, watched);
    await page.close();
  }
} finally {
  await context.close();
  fs.rmSync(work, { recursive: true, force: true });
}
finish();
