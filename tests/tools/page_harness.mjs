// What the browser tests of the pages (koppel view, koppel edit) share: counting checks, headless
// Debian Chromium through playwright-core, a page's console errors and network requests (refused:
// only file:, and the data: and blob: URLs a page makes itself, are local), and the ink of a
// screenshot.

// check(ok, what) counts and prints a failure; finish() prints the closing line and exits.
export function checker() {
  let passed = 0, failed = 0;
  return {
    check(ok, what) {
      if (ok) { passed++; } else { failed++; console.log('FAILED: ' + what); }
    },
    finish() {
      console.log(`${passed} passed, ${failed} failed`);
      process.exit(failed === 0 ? 0 : 1);
    },
  };
}

// A persistent headless context of `chromium` (the executable) with its profile under `work`.
export async function launch(browserType, chromium, work, fs, path, options) {
  const flags = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'];
  return browserType.launchPersistentContext(fs.mkdtempSync(path.join(work, 'profile-')),
    Object.assign({ executablePath: chromium, headless: true, args: flags }, options));
}

const kLocal = /^(file|data|blob):/;

// Records the page's console errors, uncaught exceptions and requests that are not local (and
// aborts those); call before goto.
export async function watch(page) {
  const watched = { errors: [], requests: [] };
  page.on('console', (m) => { if (m.type() === 'error') watched.errors.push(m.text()); });
  page.on('pageerror', (e) => watched.errors.push(String(e)));
  page.on('request', (r) => { if (!kLocal.test(r.url())) watched.requests.push(r.url()); });
  await page.route((url) => !kLocal.test(url.href), (route) => route.abort());
  return watched;
}

// No console error and no network request on the page `id`.
export function checkQuiet(check, id, watched) {
  check(watched.errors.length === 0, `${id}: console errors: ${watched.errors.join(' | ')}`);
  check(watched.requests.length === 0, `${id}: network requests: ${watched.requests.join(' ')}`);
}

// The share of pixels darker than `light` in some channel (ink) and the number of distinct
// colours (to 4 bits a channel), so that a blank or one-colour page fails.
export function inkOf(png, light) {
  let ink = 0;
  const colours = new Set();
  for (let i = 0; i < png.data.length; i += 4) {
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if (r < light || g < light || b < light) ink++;
    colours.add((r >> 4) << 8 | (g >> 4) << 4 | (b >> 4));
  }
  return { share: ink / (png.width * png.height), colours: colours.size };
}

// tests/data/hostile-names.yaml: its path (from this file's place in the source tree) and the
// names it gives, each holding markup that would run a script (an <img> or <svg> handler writing
// '[X]' into document.title) or hide the page's scripts (<!--<script>) if a page took it for HTML.
const kImg = "<img src=x onerror=\"document.title+='[X]'\">";
export const hostile = {
  file: new URL('../data/hostile-names.yaml', import.meta.url).pathname,
  title: 'offset <!--<script> "quoted" & \'single\' </script> (hostile-names)',  // the page's: the file's title and id
  fileTitle: 'offset <!--<script> "quoted" & \'single\' </script>',
  drive: 'phi, deg ' + kImg,
  s: 's, mm ' + kImg,
  mu: 'mu <!--<script>',
  k: '+K <svg onload="document.title+=\'[X]\'">',
};

// Records the dialogs a page opens (alert, confirm, prompt) and dismisses them; call before goto.
export function watchDialogs(page) {
  const dialogs = [];
  page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss().catch(() => {}); });
  return dialogs;
}

// No script of a hostile name ran on `page`: its title is `title` (no '[X]' added, over several
// animation frames: the repro's handler ran on each), no dialog opened, and no element the names
// hold (an img, anything with a handler attribute) is in the document.
export async function checkNoScriptRan(check, id, page, dialogs, title) {
  for (let frame = 0; frame < 3; ++frame) {
    await page.waitForTimeout(150);
    const now = await page.title();
    check(now === title, `${id}: document.title is '${now}', expected '${title}'`);
  }
  check(dialogs.length === 0, `${id}: dialogs opened: ${dialogs.join(' | ')}`);
  const injected = await page.evaluate(() => document.querySelectorAll('img, [onerror], [onload]').length);
  check(injected === 0, `${id}: ${injected} elements from the names' markup in the document`);
}
