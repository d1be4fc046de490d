// The documentation site (docs/build.py: mkdocs build --strict, offline) built into the build
// folder and opened page by page from disk in headless Debian Chromium:
//   node site_test.mjs KOPPEL NPM_DIR CHROMIUM PYTHON SOURCE_DIR OUT_DIR
// Every page renders (a title, text, no console error, no request beyond the disk), every
// internal link leads to a file of the site (and an anchor to an element of its page), every
// image is there and decoded, and every command of `koppel --help` has its generated page.
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL, fileURLToPath } from 'node:url';
import { checker, launch, watch, checkQuiet } from '../page_harness.mjs';

const [koppel, npmDir, chromium, python, source, out] = process.argv.slice(2);
const require = createRequire(path.resolve(npmDir, 'package.json'));
const { chromium: browserType } = require('playwright-core');
const { check, finish } = checker();

// the build: strict, so a broken link between the Markdown pages has failed it already
const started = Date.now();
const site = path.join(out, 'site');
console.log(execFileSync(python, [path.join(source, 'docs', 'build.py'), koppel, site], { encoding: 'utf8' }).trim());
const buildSeconds = (Date.now() - started) / 1000;

const pages = [];
(function walk(dir) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const file = path.join(dir, entry.name);
    if (entry.isDirectory()) walk(file);
    // 404.html is a web server's page (its assets and links are absolute from the server's root)
    else if (entry.name.endsWith('.html') && file !== path.join(site, '404.html')) pages.push(file);
  }
})(site);
check(pages.length >= 20, `only ${pages.length} pages`);

// every command koppel lists has its page
const help = execFileSync(koppel, ['--help'], { encoding: 'utf8' });
const commands = help.split('Subcommands:')[1].split('\n').filter((l) => /^  \S/.test(l)).map((l) => l.trim().split(/\s+/)[0]);
check(commands.length > 10, `koppel --help lists ${commands.length} commands`);
for (const c of commands) {
  check(fs.existsSync(path.join(site, 'commands', `${c}.html`)), `no page for koppel ${c}`);
}

const ids = new Map();  // page file -> the ids of its elements (read from the HTML)
function idsOf(file) {
  if (!ids.has(file)) {
    const html = fs.readFileSync(file, 'utf8');
    ids.set(file, new Set([...html.matchAll(/\sid="([^"]+)"/g)].map((m) => m[1])));
  }
  return ids.get(file);
}

const work = fs.mkdtempSync(path.join(out, 'browser-'));
const context = await launch(browserType, chromium, work, fs, path, { viewport: { width: 1200, height: 900 } });
let links = 0, images = 0;
for (const file of pages) {
  const id = path.relative(site, file);
  const page = await context.newPage();  // a fresh page each: its own console and requests
  const watched = await watch(page);
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
  const seen = await page.evaluate(() => ({
    title: document.title,
    h1: (document.querySelector('article h1') || {}).textContent || '',
    text: (document.querySelector('article') || document.body).innerText.length,
    links: [...document.querySelectorAll('a[href]')].map((a) => a.href),
    images: [...document.querySelectorAll('article img')].map((i) => ({ src: i.src, ok: i.complete && i.naturalWidth > 0 })),
  }));
  await page.close();
  checkQuiet(check, id, watched);
  check(seen.h1.trim().length > 0, `${id}: no heading`);
  check(seen.text > 200, `${id}: ${seen.text} characters of text`);
  for (const href of seen.links) {
    if (!href.startsWith('file:')) {
      check(/^(https?|mailto):/.test(href), `${id}: link ${href}`);
      continue;
    }
    links++;
    const url = new URL(href);
    let target = fileURLToPath(url);
    if (fs.existsSync(target) && fs.statSync(target).isDirectory()) target = path.join(target, 'index.html');
    check(target.startsWith(site) && fs.existsSync(target), `${id}: broken link ${href}`);
    if (url.hash.length > 1 && fs.existsSync(target) && target.endsWith('.html')) {
      check(idsOf(target).has(decodeURIComponent(url.hash.slice(1))), `${id}: no anchor ${url.hash} in ${path.relative(site, target)}`);
    }
  }
  for (const image of seen.images) {
    images++;
    check(image.ok, `${id}: image ${image.src} missing or not decoded`);
  }
}
await context.close();
fs.rmSync(work, { recursive: true, force: true });
console.log(`${pages.length} pages, ${links} internal links, ${images} images; site built in ${buildSeconds.toFixed(1)} s`);
check(buildSeconds < 60, `the site took ${buildSeconds} s to build`);
finish();
