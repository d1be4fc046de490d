// The page of `koppel catalog page` in headless Debian Chromium (driven by playwright-core, as the
// other pages' tests): every entry of the catalog is on it with its scheme (an SVG with ink), and
// the search box, typed into as a user would, shows exactly the entries `koppel catalog find
// --text` prints for the same words, in the same order (the reference: the CLI, whose search is
// the catalog library's; the page runs that code compiled to WebAssembly). The words are the
// ones engineers search by, English and German, with umlauts and without. No console error, no
// network request: the page works offline.
//
// usage: node catalog_page_test.mjs KOPPEL NODE_MODULES_DIR CHROMIUM CATALOG_DIR
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { checker, launch, watch, checkQuiet } from '../page_harness.mjs';

const [koppel, npmDir, chromium, catalog] = process.argv.slice(2);
const require = createRequire(path.resolve(npmDir, 'package.json'));
const { chromium: browserType } = require('playwright-core');
const { check, finish } = checker();

const kWords = ['wiper', 'Scheibenwischer', 'steering', 'Lenkung', 'hydraulic', 'Hydraulik', 'inversion', 'Umkehrung',
  'coupler curve', 'Koppelkurve', 'function generator', 'Funktionsgetriebe', 'dead center', 'Totlage', 'Rast', 'dwell',
  'Eilrücklauf', 'Eilruecklauf', 'quick return', 'Geradführung', 'straight line', 'Kniehebel', 'toggle', 'walking',
  'crank rocker', 'no such word anywhere'];

const work = fs.mkdtempSync(path.join(os.tmpdir(), 'koppel-catalog-page-'));
const context = await launch(browserType, chromium, work, fs, path, { viewport: { width: 1250, height: 1000 } });
try {
  const html = path.join(work, 'catalog.html');
  execFileSync(koppel, ['catalog', 'page', '--catalog', catalog, '-o', html]);
  const all = JSON.parse(execFileSync(koppel, ['catalog', 'list', '--catalog', catalog, '--format', 'json'])).map((e) => e.id);
  const page = await context.newPage();
  const watched = await watch(page);
  await page.goto('file://' + html);
  await page.waitForFunction(() => window.koppelCatalog && window.koppelCatalog.ready);

  // every entry, each with a drawn scheme
  const cards = await page.$$eval('section.entry', (s) => s.map((e) => ({ id: e.id, paths: e.querySelectorAll('svg *').length })));
  check(cards.length === all.length, `the page has ${cards.length} entries, the catalog ${all.length}`);
  for (const id of all) {
    const card = cards.find((c) => c.id === id);
    check(card && card.paths > 5, `${id}: no scheme on the page`);
  }

  for (const word of kWords) {
    const expected = JSON.parse(execFileSync(koppel, ['catalog', 'find', '--catalog', catalog, '--text', word, '--format', 'json'])).map((e) => e.id);
    await page.fill('#search', word);
    const shown = await page.$$eval('section.entry', (s) => s.filter((e) => !e.hidden).map((e) => e.id));
    check(JSON.stringify(shown) === JSON.stringify(expected),
      `'${word}': the page shows [${shown.join(', ')}], catalog find --text [${expected.join(', ')}]`);
    if (word !== 'no such word anywhere') check(expected.length > 0, `'${word}' finds nothing`);
  }
  await page.fill('#search', '');
  const again = await page.$$eval('section.entry', (s) => s.filter((e) => !e.hidden).length);
  check(again === all.length, `an empty search shows ${again} of ${all.length} entries`);
  checkQuiet(check, 'catalog page', watched);
  await page.close();
} finally {
  await context.close();
  fs.rmSync(work, { recursive: true, force: true });
}
finish();
