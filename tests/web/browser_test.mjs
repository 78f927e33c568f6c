// The web page tested as a user meets it: Debian's chromium, headless, WebGL2 on SwiftShader,
// driven by playwright-core; the site (scripts/build-web.sh) served on 127.0.0.1. One case
// per run, so each is its own ctest test (tests/web/CMakeLists.txt lists them):
//   node browser_test.mjs --site DIR --zeroset BIN --case NAME [--keep DIR]
// Picture cases compare the canvas with `zeroset render` of the same scene on the desktop:
// see TOLERANCE. Every case fails on any console error or uncaught exception of the page.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

// Picture tolerance: the browser traces in float (WebGL2 has no double), the desktop in
// double; the drivers round differently at silhouettes, creases and singular points. A
// pixel "differs" when a channel is off by more than 48/255; at most 3 % of the pixels may
// differ, and the surface covers the same pixels (hit or background) but for 1.5 %.
const TOLERANCE = { channel: 48, differing: 0.03, coverage: 0.015 };
const SIZE = [320, 240];
// The canvas of cases that test messages, panels or files rather than the picture: the
// browser draws every picture on the CPU (SwiftShader), so a small one saves seconds.
const SMALL = 'size=64x48';

const args = Object.fromEntries(process.argv.slice(2).reduce((a, v, i, all) =>
  (v.startsWith('--') ? [...a, [v.slice(2), all[i + 1]]] : a), []));
const site = path.resolve(args.site);
const zeroset = args.zeroset;
const sourceDir = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const scratch = args.keep ? path.resolve(args.keep) : fs.mkdtempSync(path.join(os.tmpdir(), 'zs-web-'));
fs.mkdirSync(scratch, { recursive: true });

if (!fs.existsSync(path.join(site, 'index.html')) || !fs.existsSync(path.join(site, 'zeroset.wasm'))) {
  console.error(`no web site in ${site}: run scripts/build-web.sh first`);
  process.exit(1);
}

// ---- the static server ---------------------------------------------------------------
const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json',
  '.png': 'image/png', '.surf': 'text/plain', '.jsurf': 'text/plain' };
const server = http.createServer((req, res) => {
  const url = new URL(req.url, 'http://127.0.0.1');
  const rel = decodeURIComponent(url.pathname);
  const base = rel.startsWith('/ref/') ? scratch : site;
  const file = path.join(base, rel.startsWith('/ref/') ? rel.slice(5) : rel);
  if (!file.startsWith(base) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
    res.writeHead(404);
    res.end();
    return;
  }
  res.writeHead(200, { 'Content-Type': MIME[path.extname(file)] || 'application/octet-stream' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const origin = `http://127.0.0.1:${server.address().port}`;

// ---- the browser -----------------------------------------------------------------------
// WebGL2 draws on SwiftShader behind ANGLE, as in a browser without a GPU; the page itself
// is composited on the CPU, which headless Chromium otherwise also routes through
// SwiftShader at about a quarter more time per case on two cores. With `--webgl llvmpipe`,
// ANGLE draws through the system's OpenGL ES over EGL instead: Mesa's llvmpipe, the
// desktop's own rasterizer, so that `--case bench` compares the page with the desktop on
// the same one.
const WEBGL = {
  swiftshader: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  llvmpipe: ['--use-angle=gl-egl', '--use-gl=angle', '--ignore-gpu-blocklist', '--enable-gpu'],
};
const webgl = args.webgl || 'swiftshader';
if (!WEBGL[webgl]) throw new Error(`--webgl: one of ${Object.keys(WEBGL).join(', ')}`);
const browser = await chromium.launch({
  executablePath: process.env.ZS_CHROMIUM || '/usr/bin/chromium',
  args: [...WEBGL[webgl], '--no-sandbox', '--disable-gpu-compositing'],
});
const problems = [];
// The browser speaks `locale` (navigator.languages), English unless a case asks otherwise.
async function openPage(query, { touch = false, locale = 'en-US' } = {}) {
  const context = await browser.newContext({ viewport: { width: 1000, height: 700 },
    deviceScaleFactor: 1, hasTouch: touch, locale });
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`uncaught exception: ${e.message}`));
  await page.goto(`${origin}/index.html?${query}`);
  return page;
}
async function settled(page, want = 'ready', timeout = 15000) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.documentElement.dataset.zeroset),
                             null, { timeout });
  const state = await page.evaluate(() => document.documentElement.dataset.zeroset);
  if (state !== want) {
    const error = await page.evaluate(() => document.getElementById('zeroset-error').textContent);
    throw new Error(`page state ${state}, wanted ${want}${error ? ':\n' + error : ''}`);
  }
}
// Marks the page busy, then waits for it to settle: for edits made after the first picture.
async function markBusy(page) {
  await page.evaluate(() => { document.documentElement.dataset.zeroset = 'busy'; });
}
// Pictures are compared inside the page (moving 300 000 numbers to Node costs seconds):
// `snapshot` keeps the canvas' pixels under a name, `compareWith` compares the canvas with
// a kept snapshot or with an image the server has, and returns only the statistics.
async function snapshot(page, name) {
  await page.evaluate((n) => {
    const c = document.getElementById('view');
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(c, 0, 0);
    window.__snapshots = window.__snapshots || {};
    window.__snapshots[n] = ctx.getImageData(0, 0, c.width, c.height);
  }, name);
}
async function compareWith(page, { snapshotName, imageUrl, background = [255, 255, 255] }) {
  return page.evaluate(async ({ snapshotName, imageUrl, background, tolerance }) => {
    const pixelsOf = (source, w, h) => {
      const c = document.createElement('canvas');
      c.width = w;
      c.height = h;
      const ctx = c.getContext('2d');
      ctx.drawImage(source, 0, 0);
      return ctx.getImageData(0, 0, w, h);
    };
    const view = document.getElementById('view');
    const a = pixelsOf(view, view.width, view.height);
    let b;
    if (imageUrl) {
      const bitmap = await createImageBitmap(await (await fetch(imageUrl)).blob());
      b = pixelsOf(bitmap, bitmap.width, bitmap.height);
    } else {
      b = window.__snapshots[snapshotName];
    }
    if (a.width !== b.width || a.height !== b.height)
      return { differing: 1, coverage: 1, note: `sizes ${a.width}x${a.height} and ${b.width}x${b.height}` };
    const isBackground = (d, i) => Math.abs(d[i] - background[0]) <= 3 &&
      Math.abs(d[i + 1] - background[1]) <= 3 && Math.abs(d[i + 2] - background[2]) <= 3;
    let differing = 0, coverage = 0, surface = 0;
    const n = a.width * a.height;
    for (let i = 0; i < n * 4; i += 4) {
      const d = Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]),
                         Math.abs(a.data[i + 2] - b.data[i + 2]));
      if (d > tolerance.channel) differing++;
      if (isBackground(a.data, i) !== isBackground(b.data, i)) coverage++;
      if (!isBackground(a.data, i)) surface++;
    }
    return { differing: differing / n, coverage: coverage / n, surface: surface / n };
  }, { snapshotName, imageUrl, background, tolerance: TOLERANCE });
}
function desktopRender(scene, sets, name) {
  const out = path.join(scratch, `${name}.png`);
  const argv = ['render', scene, '-o', out, '--size', `${SIZE[0]}x${SIZE[1]}`];
  for (const s of sets) argv.push('--set', s);
  const r = spawnSync(zeroset, argv, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`zeroset ${argv.join(' ')} failed:\n${r.stderr}`);
  return `/ref/${name}.png`;
}
function check(condition, message) { if (!condition) throw new Error(message); }

function pageQuery(example, sets) {
  return `example=${example}&size=${SIZE[0]}x${SIZE[1]}` +
    sets.map((s) => `&set=${encodeURIComponent(s)}`).join('');
}
// A gallery scene in the browser against `zeroset render` of it.
function matchesDesktop(example, sets = [], { page: shared } = {}) {
  return async () => {
    const name = example.replace(/\//g, '-');
    const query = pageQuery(example, sets);
    const page = shared || await openPage(query);
    if (shared && !page.url().endsWith(`?${query}`)) {
      await markBusy(page);
      await page.goto(`${origin}/index.html?${query}`);
    }
    const ref = desktopRender(path.join(sourceDir, 'examples', `${example}.surf`), sets, name);
    await settled(page);
    const background = await page.evaluate(() => window.zeroset.session.frame(1, 1).background.map((c) => Math.round(c * 255)));
    const method = await page.evaluate(() => window.zeroset.session.method());
    const r = await compareWith(page, { imageUrl: ref, background });
    console.log(`${example} (${method} in the browser): ${(100 * r.differing).toFixed(2)} % of pixels differ, ` +
                `coverage differs on ${(100 * r.coverage).toFixed(2)} %`);
    if (r.differing > TOLERANCE.differing || r.coverage > TOLERANCE.coverage) {
      await page.locator('#view').screenshot({ path: path.join(scratch, `${name}.browser.png`) });
      throw new Error(`${example}: the browser's picture is not the desktop's (${r.note || ''}); ` +
                      `both in ${scratch}`);
    }
  };
}

const cases = {};
// The pictures test.sh checks: the seven thesis surfaces and five gallery scenes, in shards
// that each stay well under 20 s on two cores.
const PICTURES = [
  ...['1-cross-channel', '2-cayley-cubic', '3-cuboid', '4-peninsula', '5-klein-quartic',
      '6-quartic-saddle', '7-racor'].map((t) => [`thesis/${t}`, []]),
  ['endrass-octic', []],   // above the float isolation's degree: double-float expansion
  ['labs-septic', []],     // a record surface clipped by a ball
  ['gyroid', []],          // not a polynomial: interval arithmetic
  ['dupin-cyclide', ['shading.color="gauss"', 'shading.curvature_range=2']],  // curvature colours
  ['torus', ['opacity=0.5']],  // transparent: kept hits, blended
  ['torus', ['shading.shadows=true', 'lights.space="camera"']],  // shadow rays; lights on the camera
  // a cross-section with its cut curve, and contour lines
  ['torus', ['clip.plane=[{normal=[0,1,1], offset=0.1}]', 'shading.contours.enabled=true',
             'shading.contours.function="x*y"', 'shading.contours.width=0.03']],
  ['torus', ['render.mode="volume"', 'background=[0.05,0.05,0.1]']],  // F's field as a volume
];
const PICTURE_SHARDS = 4;
for (let k = 0; k < PICTURE_SHARDS; k++) {
  cases[`pictures-${k + 1}-of-${PICTURE_SHARDS}`] = async () => {
    // The shard's first scene opens the page; the others load into it.
    let page = null;
    for (let i = k; i < PICTURES.length; i += PICTURE_SHARDS) {
      const [example, sets] = PICTURES[i];
      page = page || await openPage(pageQuery(example, sets));
      await matchesDesktop(example, sets, { page })();
    }
  };
}

// The whole gallery against the desktop, in one run (a benchmark of the goal "every example
// renders in the browser", not part of test.sh: about two minutes, a fifth of it the
// Sarti dodecic's JIT; tests/render/double_float_test.cpp checks its expansion's loops on
// the desktop's GL within test.sh).
cases['gallery'] = async () => {
  const gallery = JSON.parse(fs.readFileSync(path.join(site, 'examples', 'index.json'), 'utf8'));
  const page = await openPage('size=16x16');
  await settled(page);
  const failures = [];
  for (const e of gallery) {
    try {
      await matchesDesktop(e.name, [], { page })();
    } catch (err) {
      failures.push(err.message);
    }
  }
  if (failures.length) throw new Error(failures.join('\n'));
};

// Numbers for docs/PERFORMANCE.md (not part of test.sh): page load to the first picture,
// and the median of 9 full frames at 800 x 600 in the browser beside `zeroset bench` of the
// same scene on the desktop (the method the page uses), in the same run.
cases['bench'] = async () => {
  const scenes = ['thesis/2-cayley-cubic', 'thesis/3-cuboid', 'thesis/5-klein-quartic',
                  'barth-sextic', 'endrass-octic', 'gyroid'];
  console.log('| scene | method | first picture ms | browser ms | desktop ms | browser / desktop |');
  console.log('|---|---|---:|---:|---:|---:|');
  for (const scene of scenes) {
    const page = await openPage(`example=${scene}&size=800x600`);
    await settled(page, 'ready', 60000);
    const first = await page.evaluate(() => window.zeroset.firstPictureMs);
    const method = await page.evaluate(() => window.zeroset.session.method());
    const times = (await page.evaluate(() => window.zeroset.frameTimes(9))).sort((a, b) => a - b);
    const browserMs = times[Math.floor(times.length / 2)];
    await page.context().close();
    const r = spawnSync(zeroset, ['bench', path.join(sourceDir, 'examples', `${scene}.surf`), '--frames', '9'],
                        { encoding: 'utf8' });
    const row = r.stdout.split('\n').find((l) => l.startsWith(`| ${method} |`));
    const desktopMs = row ? Number(row.split('|')[2]) : NaN;
    console.log(`| ${scene} | ${method} | ${first.toFixed(0)} | ${browserMs.toFixed(1)} | ` +
                `${desktopMs.toFixed(1)} | ${(browserMs / desktopMs).toFixed(2)} |`);
  }
};

// Whatever is typed, dropped or put in the URL ends in a picture or a positioned message.
cases['bad-formulas'] = async () => {
  const page = await openPage(SMALL);
  await settled(page);
  // Unfinished, unparsable, constant (nothing to draw), far above every degree limit, long.
  const typed = ['', 'x^', '(((((x', 'x²+y²-1', '1/0', 'x^1000',
                 'x^2+y^2+z^2-1'.repeat(12).replace(/1x/g, '1+x')];
  for (const formula of typed) {
    await markBusy(page);
    await page.fill('#formula', formula);
    await page.waitForFunction(() => ['ready', 'error'].includes(document.documentElement.dataset.zeroset),
                               null, { timeout: 15000 });
    const state = await page.evaluate(() => document.documentElement.dataset.zeroset);
    if (state === 'error') {
      const message = await page.textContent('#zeroset-error');
      check(message.trim() !== '' && !/internal error/.test(message), `"${formula}": ${message}`);
    }
  }
};

// Typing: each keystroke whose text parses shows a first picture (the tape interpreter's)
// before the formula's own shader, and the last one ends in the formula's own picture.
cases['typing'] = async () => {
  const page = await openPage(`formula=${encodeURIComponent('x^2 + y^2 + z^2 - 1')}&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  await snapshot(page, 'sphere');
  // The formula field's focus links the interpreter in the background: typing starts after.
  await page.focus('#formula');
  await page.waitForFunction(() => document.documentElement.dataset.interpreter === 'linked',
                             null, { timeout: 30000 });
  await markBusy(page);
  await page.fill('#formula', '');
  await page.type('#formula', 'x^2-z^2-0.3', { delay: 40 });
  // A pause inside an unfinished prefix ("x^2-z^") may show its error for a moment: the
  // whole formula ends ready.
  await page.waitForFunction(() => document.documentElement.dataset.zeroset === 'ready',
                             null, { timeout: 15000 });
  const { count, last, ms } = await page.evaluate(() => ({
    count: Number(document.documentElement.dataset.firstPictures || 0),
    last: document.documentElement.dataset.firstPicture,
    ms: document.documentElement.dataset.firstPictureMs }));
  console.log(`${count} first pictures, the last of "${last}" in ${ms} ms`);
  check(count >= 1, 'typing showed no first picture');
  check((await compareWith(page, { snapshotName: 'sphere' })).differing > 0.1,
        'the final picture is still the sphere');
};

cases['bad-file'] = async () => {
  const page = await openPage(SMALL);
  await settled(page);
  // A damaged .jsurf file, dropped.
  await markBusy(page);
  await page.evaluate(() => {
    const dt = new DataTransfer();
    dt.items.add(new File(['surface_equation=x^^2+y^2-1\n'], 'broken.jsurf', { type: 'text/plain' }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  await settled(page, 'error');
  const jsurfError = await page.textContent('#zeroset-error');
  check(/broken\.jsurf:\d+:\d+/.test(jsurfError), `the .jsurf error has no position: ${jsurfError}`);
};

cases['bad-url-parameters'] = async () => {
  // URL parameters that are not what they should be.
  for (const query of ['example=..%2F..%2Fetc%2Fpasswd', 'scene=%%%', 'set=no.such.key%3D1']) {
    const other = await openPage(`${query}&${SMALL}`);
    await other.waitForFunction(() => ['ready', 'error'].includes(document.documentElement.dataset.zeroset),
                                null, { timeout: 15000 });
    await other.context().close();
  }
};

// Kiosk mode (kiosk=1): no file buttons and drops ignored, the formula keyboard by touch,
// a polynomial above the degree limit refused, and the start screen again once idle.
cases['kiosk'] = async () => {
  const page = await openPage(`kiosk=1&idle=2&max-degree=4&${SMALL}`, { touch: true });
  await settled(page);
  const gallery = JSON.parse(fs.readFileSync(path.join(site, 'examples', 'index.json'), 'utf8'));
  const start = await page.evaluate(() => window.zeroset.session.formula());
  check(start === gallery[0].formula, `the exhibit starts on "${start}", not the gallery's first`);
  for (const id of ['download', 'open', 'save', 'share'])
    check(!(await page.locator(`#${id}`).isVisible()), `#${id} is offered in kiosk mode`);
  check(await page.locator('#gallery-panel').evaluate((d) => d.open), 'the gallery is not open');
  await page.evaluate(() => {
    const dt = new DataTransfer();
    dt.items.add(new File(['formula = "x - y"\n'], 'dropped.surf', { type: 'text/plain' }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  });
  const tap = async (keys) => {
    for (const key of keys) await page.locator(`#formula-keyboard [data-key="${key}"]`).tap();
  };
  await tap(['clear', 'x', '^', '6', '+', 'y']);
  await page.waitForFunction(() => document.documentElement.dataset.zeroset === 'error');
  const refusal = await page.textContent('#zeroset-error');
  check(/degree 6 .*at most 4/.test(refusal), `no degree refusal: ${refusal}`);
  await tap(['clear', 'x', '^2', '+', 'y', '^2', '-', '1', 'draw']);
  // The draw key sets the formula at once; read it before the build settles, since under
  // load the build can outlast the 2 s idle time, which then returns to the start screen.
  const typed = await page.evaluate(() => window.zeroset.session.formula());
  check(typed === 'x^2+y^2-1', `the keyboard typed "${typed}"`);
  await settled(page);
  await markBusy(page);
  await page.waitForFunction(() => document.documentElement.dataset.kioskStarts === '1', null,
                             { timeout: 10000 });
  await settled(page);
  const back = await page.evaluate(() => window.zeroset.session.formula());
  check(back === start, `idle went back to "${back}", not the start screen`);
};

// A lost WebGL context comes back with the same picture.
cases['lost-context-recovers'] = async () => {
  const page = await openPage(`example=thesis/2-cayley-cubic&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  await snapshot(page, 'before');
  await markBusy(page);
  await page.evaluate(async () => {
    const ext = document.getElementById('view').getContext('webgl2').getExtension('WEBGL_lose_context');
    ext.loseContext();
    await new Promise((r) => setTimeout(r, 100));
    ext.restoreContext();
  });
  await settled(page);
  const r = await compareWith(page, { snapshotName: 'before' });
  check(r.differing === 0, `the restored picture differs (${JSON.stringify(r)})`);
};

// A light edited in the Lights panel goes through --set's validation and redraws.
cases['light-edit-redraws'] = async () => {
  const page = await openPage(`example=thesis/3-cuboid&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  await snapshot(page, 'before');
  await page.click('details[data-group="Lights"] > summary');
  await markBusy(page);
  await page.fill('#set-lights-source-1-intensity', '0');
  await page.press('#set-lights-source-1-intensity', 'Enter');
  await page.dispatchEvent('#set-lights-source-1-intensity', 'change');
  await settled(page);
  check(/intensity = 0\.0/.test(await page.evaluate(() => window.zeroset.session.sceneText())),
        'the light\'s intensity did not reach the scene');
  check((await compareWith(page, { snapshotName: 'before' })).differing > 0.05, 'the picture did not change');
  await markBusy(page);
  await page.fill('#set-lights-source-1-intensity', '-1');
  await page.dispatchEvent('#set-lights-source-1-intensity', 'change');
  await settled(page, 'error');
  check(/lights\.source\.1\.intensity/.test(await page.textContent('#zeroset-error')), 'a bad intensity names no key');
};

// A clip plane added in the Cross-sections panel cuts the surface (a frame parameter: no new
// program), its offset edits through --set, and removing it restores the picture.
cases['clip-plane-panel'] = async () => {
  const page = await openPage(`example=torus&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  await snapshot(page, 'whole');
  await page.click('details[data-group="Cross-sections"] > summary');
  await markBusy(page);
  await page.click('#clip-plane-add');
  await settled(page);
  check(/\[\[clip\.plane\]\]\nenabled = true\nnormal = \[0\.0, 0\.0, 1\.0\]\noffset = 0\.0/.test(
    await page.evaluate(() => window.zeroset.session.sceneText())), 'the plane did not reach the scene');
  const cut = await compareWith(page, { snapshotName: 'whole' });
  check(cut.differing > 0.02, `the plane cut nothing (${JSON.stringify(cut)})`);
  await markBusy(page);
  await page.fill('#set-clip-plane-1-offset', '0.2');
  await page.dispatchEvent('#set-clip-plane-1-offset', 'change');
  await settled(page);
  check(/offset = 0\.2/.test(await page.evaluate(() => window.zeroset.session.sceneText())), 'the offset did not reach the scene');
  await markBusy(page);
  await page.click('#clip-plane-1-remove');
  await settled(page);
  const back = await compareWith(page, { snapshotName: 'whole' });
  check(back.differing === 0, `removing the plane did not restore the picture (${JSON.stringify(back)})`);
};

// Several surfaces: the URL's surface= adds one, the Surface panel removes and adds them
// (each a [[surface]] table of the scene), and a bad formula there is refused at its key.
cases['surfaces-panel'] = async () => {
  const formula = encodeURIComponent('x^2 + y^2 + z^2 - 1');
  const sphere = encodeURIComponent('(x - 0.7)^2 + y^2 + z^2 - 0.36');
  // A small canvas: the case checks texts and that the picture changes, not pixels.
  const page = await openPage(`formula=${formula}&surface=${sphere}&${SMALL}`);
  await settled(page);
  const sceneText = () => page.evaluate(() => window.zeroset.session.sceneText());
  check((await sceneText()).split('[[surface]]').length === 3, 'surface= did not add a surface');
  // Hovering names the surface under the pointer: the unit sphere at the centre.
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + box.width / 2 + 1, box.y + box.height / 2 - 1, { steps: 4 });
  await page.waitForFunction(() => /K /.test(document.getElementById('status').textContent), null,
                             { timeout: 5000 }).catch(() => {});
  const status = await page.textContent('#status');
  check(/^surface 1 of 2 · .*K 1\.000 · H 1\.000/.test(status), `status: ${status}`);
  await page.mouse.move(box.x - 20, box.y - 20);
  await snapshot(page, 'two');
  await page.click('details[data-group="Surface"] > summary');
  await markBusy(page);
  await page.click('#surface-2-remove');
  await settled(page);
  check(!(await sceneText()).includes('[[surface]]'), 'the surface was not removed');
  const one = await compareWith(page, { snapshotName: 'two' });
  check(one.differing > 0.005, `removing the surface changed nothing (${JSON.stringify(one)})`);
  await markBusy(page);
  await page.click('#surface-add');
  await settled(page);
  check(/\[\[surface\]\]\nformula = "z"/.test(await sceneText()), 'the added surface is not z = 0');
  await markBusy(page);
  await page.fill('#set-surface-2-formula', 'z +* 1');
  await page.dispatchEvent('#set-surface-2-formula', 'change');
  await settled(page, 'error');
  const error = await page.textContent('#zeroset-error');
  check(/surface\.2\.formula/.test(error), `the error names no key: ${error}`);
};

// Hovering over the unit sphere reads its curvatures (src/probe): K = H = 1.
cases['hover-shows-curvature'] = async () => {
  const page = await openPage(`formula=${encodeURIComponent('x^2 + y^2 + z^2 - 1')}&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  const box = await page.locator('#view').boundingBox();
  await page.mouse.move(box.x + SIZE[0] / 2 + 3, box.y + SIZE[1] / 2 - 2, { steps: 4 });
  await page.waitForFunction(() => /K /.test(document.getElementById('status').textContent), null,
                             { timeout: 5000 }).catch(() => {});
  const status = await page.textContent('#status');
  check(/K 1\.000 · H 1\.000 · k1 1\.000 · k2 1\.000/.test(status), `status: ${status}`);
  await page.mouse.move(box.x + 2, box.y + 2, { steps: 4 });
  await page.waitForFunction(() => /no surface/.test(document.getElementById('status').textContent), null,
                             { timeout: 5000 });
};

// embed=1 shows only the picture, at the size the URL asks for.
cases['embed-and-size'] = async () => {
  const page = await openPage('example=thesis/7-racor&embed=1&size=200x150');
  await settled(page);
  check(await page.isHidden('#panel') && await page.isHidden('#panel-toggle') && await page.isHidden('#status'),
        'embed mode shows more than the picture');
  const view = await page.locator('#view').boundingBox();
  check(Math.round(view.width) === 200 && Math.round(view.height) === 150, `canvas ${JSON.stringify(view)}`);
  const size = await page.evaluate(() => [document.getElementById('view').width, document.getElementById('view').height]);
  check(size[0] === 200 && size[1] === 150, `drawing buffer ${size}`);
};

// On a phone 360 px wide: the picture fills the width above the panel, and the panel folds.
cases['phone-layout'] = async () => {
  const context = await browser.newContext({ viewport: { width: 360, height: 740 }, deviceScaleFactor: 2,
                                             hasTouch: true, isMobile: true });
  const page = await context.newPage();
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`uncaught exception: ${e.message}`));
  await page.goto(`${origin}/index.html?example=thesis/3-cuboid`);
  await settled(page, 'ready', 30000);
  const view = await page.locator('#view').boundingBox();
  const panel = await page.locator('#panel').boundingBox();
  check(view.width >= 359 && view.height > 250, `canvas ${JSON.stringify(view)}`);
  check(panel.y >= view.y + view.height - 1 && panel.width >= 359, `panel ${JSON.stringify(panel)} over the picture`);
  await page.click('#panel-toggle');
  check(await page.isHidden('#panel'), 'the panel does not fold');
  await context.close();
};

cases['bad-formula-keeps-picture'] = async () => {
  const page = await openPage(`formula=${encodeURIComponent('x^2 + y^2 + z^2 - 1')}&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page);
  await snapshot(page, 'before');
  await markBusy(page);
  await page.fill('#formula', 'x^^2 + y');
  await settled(page, 'error');
  const message = await page.textContent('#zeroset-error');
  check(/x\^\^2 \+ y/.test(message) && /\n\s*\^/.test(message), `no caret message:\n${message}`);
  check((await compareWith(page, { snapshotName: 'before' })).differing === 0,
        'the picture changed under a bad formula');
  // Fixing the formula clears the message and draws again.
  await markBusy(page);
  await page.fill('#formula', 'x^2 + y^2 - 1');
  await settled(page);
  check(await page.isHidden('#zeroset-error'), 'the error stayed after the formula was fixed');
};

cases['bad-url-shows-error-above-default'] = async () => {
  const page = await openPage(`formula=${encodeURIComponent('sin(x') }&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(page, 'error');
  const message = await page.textContent('#zeroset-error');
  check(/sin\(x/.test(message) && /\^/.test(message), `no positioned message:\n${message}`);
  await snapshot(page, 'self');
  check((await compareWith(page, { snapshotName: 'self' })).surface > 0.05, 'no default surface under the error');
  const bad = await openPage(`example=thesis/2-cayley-cubic&set=${encodeURIComponent('tracing.epsilon=-1')}&${SMALL}`);
  await settled(bad, 'error');
  check(/tracing\.epsilon/.test(await bad.textContent('#zeroset-error')), 'a bad --set names no key');
};

cases['share-link'] = async () => {
  const page = await openPage(`example=thesis/2-cayley-cubic&size=${SIZE[0]}x${SIZE[1]}` +
                              `&set=${encodeURIComponent('camera.eye=[3,2,2.5]')}&set=${encodeURIComponent('materials.front.color=[0.2,0.6,0.9]')}`);
  await settled(page);
  const pictureUrl = await page.evaluate(() => document.getElementById('view').toDataURL('image/png'));
  await page.click('#share');
  await page.waitForFunction(() => document.getElementById('share-link').value !== '');
  const link = new URL(await page.inputValue('#share-link'));
  const shared = await openPage(`${link.searchParams.toString()}&size=${SIZE[0]}x${SIZE[1]}`);
  await settled(shared);
  const r = await compareWith(shared, { imageUrl: pictureUrl });
  check(r.differing === 0 && r.coverage === 0, `the shared link draws another picture (${JSON.stringify(r)})`);
};

cases['touch-drag-turns'] = async () => {
  const page = await openPage(`example=thesis/3-cuboid&size=${SIZE[0]}x${SIZE[1]}`, { touch: true });
  await settled(page);
  await snapshot(page, 'before');
  const eyeBefore = await page.evaluate(() => window.zeroset.session.settings().find((s) => s.key === 'camera.eye').value);
  const box = await page.locator('#view').boundingBox();
  const cdp = await page.context().newCDPSession(page);
  const at = (x, y) => [{ x: box.x + x, y: box.y + y, id: 1 }];
  await markBusy(page);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(160, 120) });
  for (let k = 1; k <= 6; k++)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(160 + 12 * k, 120 + 4 * k) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await settled(page);
  const eyeAfter = await page.evaluate(() => window.zeroset.session.settings().find((s) => s.key === 'camera.eye').value);
  check(JSON.stringify(eyeBefore) !== JSON.stringify(eyeAfter), 'a touch drag did not move the camera');
  check((await compareWith(page, { snapshotName: 'before' })).differing > 0.01, 'the picture did not turn');
};

cases['drop-surf-loads'] = async () => {
  const page = await openPage(SMALL);
  await settled(page);
  await markBusy(page);
  const text = fs.readFileSync(path.join(sourceDir, 'examples', 'torus.surf'), 'utf8');
  await page.evaluate((t) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], 'torus.surf', { type: 'text/plain' }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, text);
  await settled(page);
  const formula = await page.inputValue('#formula');
  check(formula === await page.evaluate(() => window.zeroset.session.formula()) && /x\^2/.test(formula) && formula !== 'x^2 + y^2 + z^2 - 1',
        `the dropped torus did not load (formula ${formula})`);
};

// A surf script dropped on the page (docs/surf-scripts.md): its surface, with the formula
// the script wrote (the script's turns go into the camera).
cases['drop-pic-loads'] = async () => {
  const page = await openPage(SMALL);
  await settled(page);
  await markBusy(page);
  const text = fs.readFileSync(path.join(sourceDir, 'tests', 'surfscript', 'data', 'cone_turned.pic'), 'utf8');
  await page.evaluate((t) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], 'cone_turned.pic', { type: 'text/plain' }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, text);
  await settled(page);
  const formula = await page.inputValue('#formula');
  check(formula === 'x^2 + y^2 - z^2 - 0.2', `the dropped surf script did not load (formula ${formula})`);
};

// The page's languages (docs/languages.md): the browser's language picks Spanish, lang=
// overrides it, the menu switches to German and back, and the core's own messages (a parse
// error, the kiosk's refusal) and the keyboard's words follow. Expected texts come from po/*.po.
function catalog(code) {
  const messages = new Map();
  const text = fs.readFileSync(path.join(sourceDir, 'po', `${code}.po`), 'utf8');
  const unquote = (s) => JSON.parse(s);
  for (const m of text.matchAll(/^msgid (".*")\nmsgstr (".*")$/gm)) messages.set(unquote(m[1]), unquote(m[2]));
  return (english) => {
    if (!messages.get(english)) throw new Error(`po/${code}.po has no translation of "${english}"`);
    return messages.get(english);
  };
}
cases['languages'] = async () => {
  const es = catalog('es'), de = catalog('de');
  const texts = (page) => page.evaluate(() => ({
    lang: document.documentElement.lang,
    gallery: document.querySelector('#gallery-panel summary').textContent,
    reset: document.getElementById('reset').textContent,
    search: document.getElementById('gallery-search').placeholder,
    epsilon: document.querySelector('label[for="set-tracing-epsilon"]').textContent,
    caption: document.querySelector('#gallery li span').textContent,
  }));
  const page = await openPage(SMALL, { locale: 'es-ES' });
  await settled(page);
  let t = await texts(page);
  check(t.lang === 'es', `the Spanish browser got "${t.lang}"`);
  check(t.gallery === es('Gallery') && t.reset === es('Reset view') &&
        t.search === es('search the gallery'), `not in Spanish: ${JSON.stringify(t)}`);
  check(t.epsilon === `${es('tracing')} · ${es('epsilon')}`, `the epsilon label reads "${t.epsilon}"`);
  const gallery = JSON.parse(fs.readFileSync(path.join(site, 'examples', 'index.json'), 'utf8'));
  check(t.caption === es(gallery[0].title), `the gallery's first title reads "${t.caption}"`);

  // A mistake as the person types it, explained in their language (the parser's messages).
  await page.fill('#formula', 'x^2 +');
  await page.waitForFunction(() => !document.getElementById('zeroset-error').hidden);
  const mistake = await page.textContent('#zeroset-error');
  check(mistake.includes(es('complete the expression')), `the parse error is not Spanish: ${mistake}`);
  await page.fill('#formula', 'x^2 + y^2 + z^2 - 1');
  await page.selectOption('#language', 'de');
  t = await texts(page);
  check(t.lang === 'de' && t.gallery === de('Gallery') && t.reset === de('Reset view') &&
        t.epsilon === `${de('tracing')} · ${de('epsilon')}`, `not in German: ${JSON.stringify(t)}`);
  await page.selectOption('#language', 'en');
  t = await texts(page);
  check(t.gallery === 'Gallery' && t.epsilon === 'tracing.epsilon' && t.caption === gallery[0].title,
        `not back in English: ${JSON.stringify(t)}`);

  // lang= overrides the browser's Spanish.
  const kiosk = await openPage(`kiosk=1&max-degree=4&lang=de&${SMALL}`,
                               { touch: true, locale: 'es-ES' });
  await settled(kiosk);
  check((await texts(kiosk)).gallery === de('Gallery'), 'lang=de does not override the browser');
  const draw = await kiosk.textContent('#formula-keyboard [data-key="draw"]');
  check(draw === de('draw'), `the draw key reads "${draw}"`);
  for (const key of ['clear', 'x', '^', '6', '+', 'y'])
    await kiosk.locator(`#formula-keyboard [data-key="${key}"]`).tap();
  await kiosk.waitForFunction(() => document.documentElement.dataset.zeroset === 'error');
  const refusal = await kiosk.textContent('#zeroset-error');
  const wanted = de('degree %d is more than this exhibit draws (at most %d): try a formula of lower degree')
    .replace('%d', '6').replace('%d', '4');
  check(refusal.includes(wanted), `the refusal is not German: ${refusal}`);
};

// Cases that share one browser in test.sh (a browser's start is a second of a short case).
const GROUPS = {
  errors: ['bad-formula-keeps-picture', 'bad-url-shows-error-above-default'],
  files: ['drop-surf-loads', 'bad-file'],
  imports: ['drop-pic-loads'],
  layouts: ['embed-and-size', 'phone-layout'],
  pointer: ['hover-shows-curvature', 'touch-drag-turns'],
  links: ['share-link', 'bad-url-parameters'],
  panels: ['light-edit-redraws', 'clip-plane-panel'],
  'surfaces-and-lost-context': ['surfaces-panel', 'lost-context-recovers'],
};
for (const [group, members] of Object.entries(GROUPS)) {
  cases[group] = async () => {
    for (const member of members) {
      await cases[member]();
      console.log(`${member}: passed`);
    }
  };
}

// ---- run one case ------------------------------------------------------------------------
const name = args.case;
let failed = false;
try {
  if (!cases[name]) throw new Error(`no case ${name}; cases: ${Object.keys(cases).join(', ')}`);
  await cases[name]();
  if (problems.length) throw new Error(problems.join('\n'));
  console.log(`${name}: passed`);
} catch (e) {
  failed = true;
  console.error(`${name}: FAILED\n${e.message}`);
  if (problems.length) console.error(problems.join('\n'));
}
await browser.close();
server.close();
if (!args.keep && !failed) fs.rmSync(scratch, { recursive: true, force: true });
process.exit(failed ? 1 : 0);
