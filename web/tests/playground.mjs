// web/tests/playground.mjs: the playground page (web/playground/) in headless Chromium, driven
// through the DevTools protocol by playwright-core (no browser download: it runs the system's
// Chromium, CHROMIUM or /usr/bin/chromium).
//
//   bash web/build.sh --renderer && cargo build -p rtc && (cd web && npm ci) && node web/tests/playground.mjs
//   node web/tests/playground.mjs --screenshot docs/gallery/playground.png   (also saves a screenshot)
//
// The page is served from web/ by a small static server in this script. Checked:
// - diagnostics: a type error typed into examples/hello is an error at its line (the state, the
//   gutter, the tinted line with its inline message, the list), a syntax error too, and fixing
//   either clears them; the page has no uncaught exception;
// - rendering (when Chromium gives an adapter; with `--enable-unsafe-webgpu` headless Chromium on
//   Linux has SwiftShader's): hello at 160×120 accumulated to 8 spp in the canvas has
//   PSNR ≥ 40 dB against `rtc render` of the same scene, size and spp (RTC_BIN, default
//   target/debug/rtc); while the source has an error the canvas keeps its pixels; the fix (another
//   albedo) re-creates the renderer and the new image matches `rtc render` of the edited scene;
//   a drag on the canvas orbits the camera and the wheel zooms (the accumulation restarts and
//   refines again), an edit (a new renderer) keeps the moved camera, a double-click restores the
//   scene's camera and exactly its image;
//   every example web/pkg/examples.json offers for rendering renders (64 px wide, 1 spp), those
//   with asset files fetching them from the URLs beside the page (custom geometry included), and
//   each one it marks check-only (`noRender`; none now) compiles and shows the renderer's error;
//   examples/three_spheres (its sky.png fetched) matches `rtc render`; a file dropped on the page
//   (an OBJ) is used by the scene that names it, and that image matches `rtc render` of the edited
//   scene with the file beside it; cornell_box at 8 spp (128×128) matches `rtc render` as hello does;
// - without WebGPU (navigator.gpu removed; or Chromium without --enable-unsafe-webgpu, whose
//   requestAdapter() finds none on Linux), the page says the renderer needs WebGPU and still
//   checks (the diagnostic at its line).
// With no WebGPU adapter in Chromium the rendering part is skipped with a message (the renderer is
// also covered by web/tests/render.mjs under Node and Dawn); RTC_BROWSER_GPU_REQUIRED=1 makes
// that a failure.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { createServer } from 'node:http';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync, copyFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { extname, join, normalize, sep } from 'node:path';
import { chromium } from 'playwright-core';
import { repo } from './files.mjs';
import { decodePng, psnrRgbaRgb } from './png.mjs';

const args = process.argv.slice(2);
const screenshot = args.includes('--screenshot') ? args[args.indexOf('--screenshot') + 1] : null;
const rtc = process.env.RTC_BIN ?? join(repo, 'target', 'debug', 'rtc');
const executablePath = process.env.CHROMIUM ?? '/usr/bin/chromium';
const gpuRequired = process.env.RTC_BROWSER_GPU_REQUIRED === '1';
for (const [what, path] of [['web/pkg/web (bash web/build.sh --renderer)', join(repo, 'web/pkg/web/rtc_web.js')], ['web/pkg/examples.json (bash web/build.sh)', join(repo, 'web/pkg/examples.json')], ['Chromium (apt-get install chromium, or CHROMIUM=…)', executablePath]]) {
  if (!existsSync(path)) throw new Error(`${path} is missing: ${what}`);
}

// ---- a static server for web/ ----------------------------------------------------------------

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm' };
const root = join(repo, 'web');
const server = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  let file = normalize(join(root, path));
  if (!file.startsWith(root + sep)) return res.writeHead(403).end();
  if (path.endsWith('/')) file = join(file, 'index.html');
  let body;
  try {
    body = readFileSync(file);
  } catch {
    return res.writeHead(404).end();
  }
  res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'text/plain; charset=utf-8' }).end(body);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const base = `http://127.0.0.1:${server.address().port}`;

// ---- helpers -------------------------------------------------------------------------------

let passed = 0;
function ok(name) {
  passed += 1;
  console.log(`ok - ${name}`);
}

const browser = await chromium.launch({ executablePath, args: ['--enable-unsafe-webgpu'] });
const pageErrors = [];

async function openPage(query, { noGpu = false, on = browser } = {}) {
  const context = await on.newContext({ viewport: { width: 1200, height: 660 } });
  if (noGpu) {
    await context.addInitScript(() => Object.defineProperty(Navigator.prototype, 'gpu', { get: () => undefined }));
  }
  const page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(`${query}: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') console.log(`  console error: ${m.text()}`);
  });
  await page.goto(`${base}/playground/?${query}`);
  await page.waitForFunction(() => window.rtcPlayground?.state.ready, null, { timeout: 60_000 });
  return page;
}

const state = (page) => page.evaluate(() => JSON.parse(JSON.stringify(window.rtcPlayground.state)));

/** Waits until the check of the last edit has run (the debounce is 150 ms). */
async function settled(page, checksBefore) {
  await page.waitForFunction((n) => window.rtcPlayground.state.checks > n && !window.rtcPlayground.state.checking, checksBefore, { timeout: 30_000 });
}

/** Waits until the image on the canvas is of `source` (or the page's source) at ≥ `spp` and idle. */
async function rendered(page, spp, timeout = 180_000) {
  await page.waitForFunction(
    (spp) => {
      const s = window.rtcPlayground.state;
      const source = document.getElementById('source').value;
      return (s.renderedSource === source && s.spp >= spp && !s.rendering) || s.renderError;
    },
    spp,
    { timeout },
  );
  const s = await state(page);
  assert.equal(s.renderError, null, `render failed: ${s.renderError}`);
  return s;
}

const canvasRgba = (page) =>
  page.evaluate(() => {
    const c = document.getElementById('canvas');
    return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
  });

/** Selects `find` (the first occurrence after `after`) in the editor and types `text` over it. */
async function typeOver(page, find, text, after = '') {
  const checks = (await state(page)).checks;
  await page.evaluate(
    ([find, after]) => {
      const t = document.getElementById('source');
      const at = t.value.indexOf(find, Math.max(0, t.value.indexOf(after)));
      if (at < 0) throw new Error(`${find} not in the editor`);
      t.focus();
      t.setSelectionRange(at, at + find.length);
    },
    [find, after],
  );
  await page.keyboard.type(text);
  await settled(page, checks);
}

/** The 1-based line of `needle` in `text`. */
const lineOf = (text, needle) => text.slice(0, text.indexOf(needle)).split('\n').length;

/** `rtc render` of `scene` (a path, or { dir, file, text, extra? } for an edited copy; `extra`: file
 * name → path of a file to put beside it) → { width, height, rgb }. */
function nativeRender(scene, width, height, spp) {
  const tmp = mkdtempSync(join(tmpdir(), 'rtc-playground-'));
  try {
    let path = scene;
    if (typeof scene !== 'string') {
      for (const f of ['rtc.registry.json']) copyFileSync(join(repo, scene.dir, f), join(tmp, f));
      for (const [name, from] of Object.entries(scene.extra ?? {})) copyFileSync(join(repo, from), join(tmp, name));
      path = join(tmp, scene.file);
      writeFileSync(path, scene.text);
    }
    const png = join(tmp, 'native.png');
    execFileSync(rtc, ['render', path, '--size', `${width}x${height}`, '--spp', `${spp}`, '-o', png], { cwd: repo, stdio: ['ignore', 'ignore', 'inherit'] });
    return decodePng(readFileSync(png));
  } finally {
    rmSync(tmp, { recursive: true, force: true });
  }
}

function compare(label, rgba, s, native) {
  const [width, height] = s.size;
  assert.deepEqual([native.width, native.height], [width, height], `${label}: sizes differ`);
  const { psnr, differing } = psnrRgbaRgb(rgba, native.rgb, width * height);
  console.log(`  ${label}: ${width}x${height} ${s.spp} spp, ${s.frameMs.toFixed(1)} ms per pass: PSNR ${psnr.toFixed(2)} dB against rtc render, ${differing} pixels differ`);
  assert.ok(psnr >= 40, `${label}: PSNR ${psnr.toFixed(2)} dB < 40`);
}

const mean = (rgba) => rgba.reduce((sum, v, i) => (i % 4 === 3 ? sum : sum + v), 0) / ((rgba.length / 4) * 3);

// ---- the test ------------------------------------------------------------------------------

const SPP = 8;
const entry = 'examples/hello/scene.rt';
const helloText = readFileSync(join(repo, entry), 'utf8');
const page = await openPage(`example=hello/scene.rt&spp=${SPP}&scale=0.5`);
const first = await state(page);
const gpu = first.gpu !== null;
console.log(`  WebGPU in Chromium: ${gpu ? first.gpu : `none (${first.gpuError})`}`);
if (!gpu && gpuRequired) throw new Error(`no WebGPU adapter in Chromium: ${first.gpuError}`);
assert.equal(first.ok, true, 'examples/hello checks and compiles');
assert.equal(await page.inputValue('#source'), helloText);
ok('the page loads the compiler, the examples and examples/hello (checked and compiled clean)');

let good = null;
if (gpu) {
  const s = await rendered(page, SPP);
  good = await canvasRgba(page);
  compare('hello', good, s, nativeRender(entry, s.size[0], s.size[1], SPP));
  ok(`hello in the canvas matches rtc render (${SPP} spp, PSNR ≥ 40 dB)`);
}

// A type error: `true` for a vec3f's component.
const greyLine = lineOf(helloText, 'let grey');
await typeOver(page, '0.5', 'true', 'let grey');
{
  const s = await state(page);
  assert.equal(s.ok, false);
  const d = s.diagnostics.find((d) => d.severity === 'error');
  assert.ok(d, 'an error diagnostic');
  assert.deepEqual([d.file, d.line], [entry, greyLine], d.rendered);
  const gutterClass = await page.getAttribute(`#gutter-lines div:nth-child(${greyLine})`, 'class');
  assert.equal(gutterClass, 'error');
  const lineClass = await page.getAttribute(`#backdrop .line[data-line="${greyLine}"]`, 'class');
  assert.match(lineClass, /error/);
  const inline = await page.textContent(`#backdrop .line[data-line="${greyLine}"] .inline`);
  assert.ok(inline.startsWith('error'), inline);
  assert.ok((await page.locator('#diagnostics li.error').count()) >= 1);
  assert.match(await page.textContent('#check-status'), /error/);
  // No other line is marked.
  assert.equal(await page.locator('#gutter-lines div.error').count(), 1);
  ok(`a type error typed at line ${greyLine} is marked there (gutter, line, inline message, list): ${d.message}`);
}
if (gpu) {
  await page.waitForTimeout(500);
  const s = await state(page);
  assert.deepEqual(await canvasRgba(page), good, 'the canvas changed while the source had an error');
  assert.equal(await page.isVisible('#overlay'), true);
  assert.equal(s.renders, 1);
  ok('while the source has an error, the canvas keeps the last good image (and says so)');
}
if (screenshot) {
  await page.screenshot({ path: screenshot });
  console.log(`  saved ${screenshot}`);
}

// The fix: another albedo, a clean compile and a new render.
await typeOver(page, 'true', '0.9', 'let grey');
{
  const s = await state(page);
  assert.equal(s.ok, true, JSON.stringify(s.diagnostics));
  assert.equal(s.diagnostics.filter((d) => d.severity === 'error').length, 0);
  assert.equal(await page.locator('#gutter-lines div.error').count(), 0);
  assert.equal(await page.locator('#diagnostics li.error').count(), 0);
  ok('fixing it clears the marks');
}
if (gpu) {
  const s = await rendered(page, SPP);
  assert.equal(s.renders, 2, 'the fix re-created the renderer');
  const fixed = await canvasRgba(page);
  assert.ok(mean(fixed) > mean(good) + 1, `a brighter floor: mean ${mean(fixed).toFixed(1)} vs ${mean(good).toFixed(1)}`);
  const text = await page.inputValue('#source');
  compare('hello, albedo 0.9', fixed, s, nativeRender({ dir: 'examples/hello', file: 'scene.rt', text }, s.size[0], s.size[1], SPP));
  ok('after the fix the scene re-renders, and matches rtc render of the edited scene');

  // The camera: a drag orbits (a new image, the accumulation restarted and refined again to the
  // target), a double-click goes back to the scene's camera, whose accumulation is bit for bit the
  // one before the drag (the same camera bytes and the same passes' random numbers).
  const box = await page.locator('#canvas').boundingBox();
  const [cx, cy] = [box.x + box.width / 2, box.y + box.height / 2];
  const moved = async (act) => {
    const before = (await state(page)).cameraMoves;
    await act();
    await page.waitForFunction((n) => window.rtcPlayground.state.cameraMoves > n, before, { timeout: 30_000 });
    return rendered(page, SPP);
  };
  assert.equal(await page.isVisible('#camera-hint'), true, 'the camera hint is shown');
  let m = await moved(async () => {
    await page.mouse.move(cx, cy);
    await page.mouse.down();
    await page.mouse.move(cx + 60, cy + 10, { steps: 6 });
    await page.mouse.up();
  });
  const orbited = await canvasRgba(page);
  assert.ok(m.spp >= SPP && m.renders === 2, `refined again by the same renderer: ${JSON.stringify([m.spp, m.renders])}`);
  const changed = orbited.filter((v, i) => v !== fixed[i]).length;
  assert.ok(changed > orbited.length / 20, `the drag moved the view (${changed} bytes changed)`);
  m = await moved(() => page.mouse.wheel(0, -300));
  assert.notDeepEqual(await canvasRgba(page), orbited, 'the wheel zoomed');
  // An edit keeps the moved camera (a new renderer, the same view), as rtc view does after a reload.
  const view = m.view;
  await typeOver(page, '0.9', '0.8', 'let grey');
  m = await rendered(page, SPP);
  assert.equal(m.renders, 3, 'the edit re-created the renderer');
  assert.deepEqual(m.view, view, 'the edit kept the moved camera');
  await typeOver(page, '0.8', '0.9', 'let grey');
  m = await rendered(page, SPP);
  assert.deepEqual(m.view, view);
  m = await moved(() => page.mouse.dblclick(cx, cy));
  assert.deepEqual(await canvasRgba(page), fixed, 'a double-click restores the scene camera and its image');
  ok(`a drag orbits and the wheel zooms (accumulation restarted, refined to ${SPP} spp again); an edit keeps the moved camera; a double-click restores the scene's camera bit for bit`);
}

// A syntax error on a line of its own, then "revert".
{
  const ballLine = lineOf(helloText, 'object ball');
  await typeOver(page, 'object ball', 'let = ;\n    object ball');
  const s = await state(page);
  const d = s.diagnostics.find((d) => d.severity === 'error');
  assert.ok(d && d.file === entry && d.line === ballLine, JSON.stringify(s.diagnostics));
  assert.equal(await page.getAttribute(`#gutter-lines div:nth-child(${ballLine})`, 'class'), 'error');
  const checks = s.checks;
  await page.click('#revert');
  await settled(page, checks);
  assert.equal(await page.inputValue('#source'), helloText);
  assert.equal((await state(page)).ok, true);
  ok(`a syntax error at line ${ballLine} is marked there; "revert" restores the example`);
}

// Every example: the ones offered for rendering render, the check-only ones compile and say why
// they cannot render.
if (gpu) {
  await page.selectOption('#scale', '0.25');
  await page.fill('#target', '1');
  await page.dispatchEvent('#target', 'change');
  const examples = JSON.parse(readFileSync(join(repo, 'web/pkg/examples.json'), 'utf8'));
  for (const ex of examples) {
    for (const ent of ex.entries) {
      const value = `${ex.name}/${ent.file}`;
      const before = await state(page);
      await page.selectOption('#example', value);
      await page.waitForFunction(
        ([value, checks]) => {
          const s = window.rtcPlayground.state;
          return `${s.example.name}/${s.example.file}` === value && s.checks > checks && !s.checking;
        },
        [value, before.checks],
        { timeout: 60_000 },
      );
      const checkOnly = !!ex.noRender;
      if (checkOnly) {
        await page.waitForFunction(() => window.rtcPlayground.state.renderError, null, { timeout: 120_000 });
        const s = await state(page);
        assert.equal(s.ok, true, `${value} compiles`);
        console.log(`  ${value}: check-only, the renderer says: ${s.renderError.split('\n')[0]}`);
      } else {
        const s = await rendered(page, 1);
        assert.equal(s.ok, true);
        for (const a of ex.assets) assert.ok(s.fetched.includes(`examples/${ex.name}/${a}`), `${value} fetched ${a}`);
        // A scene with a fetched texture, compared where the page's image has as many samples as
        // `rtc render`'s (three_spheres draws 4 a pass). At a 1-spp target the page's pinhole
        // camera still jitters (the renderer keeps the scene's `samples`, 4) while `rtc render
        // --spp 1` samples pixel centres, so 1-spp images of other scenes differ at edges.
        if (value === 'three_spheres/scene.rt') {
          compare('three_spheres (sky.png fetched)', await canvasRgba(page), s, nativeRender(`examples/${value}`, s.size[0], s.size[1], s.spp));
        }
        console.log(`  ${value}: ${s.size.join('x')}, ${s.frameMs.toFixed(0)} ms for the pass${ex.assets.length ? `, fetched ${ex.assets.join(', ')}` : ''}`);
      }
    }
  }
  ok('every example offered for rendering renders (assets fetched from URLs; three_spheres matches rtc render); every check-only one compiles and shows the renderer\'s error');

  // A dropped file: the OBJ joins the example's folder and the scene names it (as a Lambert
  // object: a mirror bunny's reflections follow its interpolated normals, where SwiftShader's and
  // lavapipe's rounding differ; at hello's first size and spp, as above).
  await page.selectOption('#scale', '0.5');
  await page.fill('#target', String(SPP));
  await page.dispatchEvent('#target', 'change');
  await page.selectOption('#example', 'hello/scene.rt');
  await page.waitForFunction(() => window.rtcPlayground.state.example.name === 'hello' && !window.rtcPlayground.state.checking);
  await rendered(page, 1);
  const obj = readFileSync(join(repo, 'examples/assets/bunny-6k.obj'));
  await page.evaluate(async (bytes) => {
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(bytes)], 'my-bunny.obj'));
    document.getElementById('source').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [...obj]);
  await page.waitForFunction(() => window.rtcPlayground.state.dropped.includes('my-bunny.obj'));
  await typeOver(page, 'sphere_mesh(3u)', 'load_mesh("my-bunny.obj")');
  await typeOver(page, 'Mirror {}', 'grey');
  {
    const s = await rendered(page, SPP);
    assert.ok(!s.fetched.includes('examples/hello/my-bunny.obj'), 'a dropped file is not fetched');
    const text = await page.inputValue('#source');
    const native = nativeRender({ dir: 'examples/hello', file: 'scene.rt', text, extra: { 'my-bunny.obj': 'examples/assets/bunny-6k.obj' } }, s.size[0], s.size[1], s.spp);
    compare('hello with a dropped OBJ', await canvasRgba(page), s, native);
  }
  ok('a dropped OBJ is used by the scene that names it (matches rtc render with the file beside the scene)');

  // cornell_box at the first size and spp, as hello above (the issue's second scene).
  await page.selectOption('#example', 'cornell_box/scene.rt');
  await page.waitForFunction(() => window.rtcPlayground.state.example.name === 'cornell_box' && !window.rtcPlayground.state.checking);
  {
    const s = await rendered(page, SPP);
    compare('cornell_box', await canvasRgba(page), s, nativeRender('examples/cornell_box/scene.rt', s.size[0], s.size[1], SPP));
  }
  ok(`cornell_box in the canvas matches rtc render (${SPP} spp, PSNR ≥ 40 dB)`);
} else {
  console.log('  skipped: rendering (no WebGPU adapter in Chromium; web/tests/render.mjs covers the renderer under Dawn)');
}
// Edit → WGSL in the page (check + compile of each clean source; the first is the page's first
// compile after loading): figures for docs/bench/wasm_compile.md, not asserted.
{
  const times = (await state(page)).compileMs;
  const warm = times.slice(1).sort((a, b) => a - b);
  console.log(`  edit → WGSL in the page: first ${times[0]} ms, then median ${warm[warm.length >> 1]} ms, min ${warm[0]} ms over ${warm.length} compiles`);
}
await page.context().close();

// Without WebGPU: no navigator.gpu, and (Chromium without --enable-unsafe-webgpu on Linux) a
// navigator.gpu whose requestAdapter() gives no adapter.
const plain = await chromium.launch({ executablePath });
for (const [how, options, expect] of [
  ['without navigator.gpu', { noGpu: true }, /needs WebGPU/],
  ['with no WebGPU adapter', { on: plain }, /needs WebGPU|no adapter/],
]) {
  const p = await openPage('example=hello/scene.rt', options);
  const s = await state(p);
  if (how === 'with no WebGPU adapter' && s.gpu !== null) {
    console.log(`  skipped: Chromium without --enable-unsafe-webgpu has an adapter here (${s.gpu})`);
  } else {
    assert.equal(s.gpu, null);
    assert.match(await p.textContent('#render-status'), expect);
  }
  await typeOver(p, '0.5', 'true', 'let grey');
  const d = (await state(p)).diagnostics.find((d) => d.severity === 'error');
  assert.ok(d && d.line === greyLine);
  ok(`${how} the page says the renderer needs WebGPU, and still checks`);
  await p.context().close();
}
await plain.close();

assert.deepEqual(pageErrors, [], 'uncaught exceptions in the page');
ok('no uncaught exception in the page');
await browser.close();
server.close();
console.log(`${passed} passed`);
