// web/playground/playground.js: the playground's logic (an ES module, no dependencies).
//
// It loads rtc's WebAssembly package (../pkg/web, built by `bash web/build.sh --renderer`) and the
// examples index (../pkg/examples.json, written by web/playground/examples.sh). The editor holds
// one scene file of an example; the example's other files (its registry, other scene files) are
// given to the compiler unchanged, all under examples/NAME/FILE as `rtc` at the repository's root
// names them.
//
// What it guarantees:
// - 150 ms after the last keystroke the source is checked (WebCompiler.check, parsed modules
//   cached); every diagnostic of the edited file marks its line (gutter, line tint, wavy underline
//   of the primary span, the message at the line's end) and all are listed with rtc's rendered text.
// - A clean check is compiled (WebCompiler.compile: link errors and warnings, WGSL, manifest);
//   a clean compile of a source that differs from the one on screen re-creates the WebRenderer and
//   accumulates one pass per animation frame into the canvas (readRgba8 → putImageData) until the
//   target spp. A source with errors, or a renderer that fails, leaves the last good image.
// - A camera with `position` and `look_at` (WebRenderer.canOrbit) moves as in `rtc view`: drag to
//   orbit, shift- or right-drag to pan, wheel to zoom, double-click back to the scene's camera;
//   each move restarts the accumulation at one pass. A new renderer (an edit) keeps the camera the
//   user moved, as `rtc view` does after a reload; double-click goes back to the scene's.
// - Assets (OBJ, PNG/EXR/JPEG, glTF/GLB and the buffers and images a glTF names) come from URLs
//   next to the page (../pkg/examples/NAME/, copied there by examples.sh) or from files the user
//   drops on the page, which join the example's folder under their names (a dropped file wins over
//   a fetched one). pkg.loadRenderer asks for each file the scene needs; rtc confines the paths to
//   the scene's folder before asking, as `rtc render` does on disk. Fetched and dropped files are
//   kept and given to the compiler too (a `model` file is linked from its contents).
// - Without WebGPU (no navigator.gpu, no adapter, or a package built without the renderer) the page
//   still checks and compiles, and says why it cannot render.
// - window.rtcPlayground.state mirrors what the page shows, for web/tests/playground.mjs.

const $ = (id) => document.getElementById(id);
const ui = {
  example: $('example'),
  target: $('target'),
  scale: $('scale'),
  revert: $('revert'),
  gpu: $('gpu'),
  gutter: $('gutter-lines'),
  backdrop: $('backdrop'),
  source: $('source'),
  checkStatus: $('check-status'),
  diagnostics: $('diagnostics'),
  canvas: $('canvas'),
  overlay: $('overlay'),
  stats: $('stats'),
  cameraHint: $('camera-hint'),
  dropped: $('dropped'),
  renderStatus: $('render-status'),
  wgslPick: $('wgsl-pick'),
  wgsl: $('wgsl'),
};

/** What the page shows, for tests and the curious (window.rtcPlayground.state). */
const state = {
  ready: false,
  gpu: null, // the adapter's description once initGpu succeeded
  gpuError: null, // why the page cannot render, when it cannot
  example: null, // { name, file, scene }
  checks: 0, // checks run (one per debounced edit)
  checking: false, // an edit is waiting for its check
  diagnostics: [], // of the last check or compile
  ok: null, // the last check/compile had no error
  renders: 0, // renderers created
  rendering: false, // a renderer is accumulating
  renderError: null, // the last renderer's error, until the next renderer starts
  renderedSource: null, // the source of the image on the canvas
  spp: 0, // samples per pixel accumulated in the image on the canvas
  targetSpp: 0,
  frameMs: null, // wall time of the last pass: accumulate(1) + readRgba8
  size: null, // [width, height] of the image on the canvas
  cameraMoves: 0, // batches of camera moves applied (each restarts the accumulation)
  view: null, // the camera ({ position, lookAt }) when it can move
  fetched: [], // asset paths fetched from URLs, in order
  compileMs: [], // edit → WGSL of every clean check: check + compile, ms
  dropped: [], // names of the files the user dropped
  loading: false, // a renderer is being created (compile, asset fetches, BVHs, pipelines)
};
window.rtcPlayground = { state };

let pkg = null; // the wasm module's exports
let compiler = null; // one WebCompiler: parsed modules are cached between checks
let examples = []; // the index
let files = new Map(); // path → text of the current example
let entry = null; // the edited file's path (examples/NAME/FILE)
let original = ''; // the edited file as loaded
let debounce = 0;
let job = null; // the running render: { renderer, source, cancelled, running }
let assets = new Map(); // path → Uint8Array: asset files of the current example fetched so far
const dropped = new Map(); // file name → Uint8Array: files the user dropped (any example's folder)
let loads = 0; // renderers asked for; a load that is no longer the newest is discarded

// ---- the editor ------------------------------------------------------------------------------

const LINE_HEIGHT = 18; // px, as in playground.css (--line)

function escapeHtml(s) {
  return s.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

/** Redraws the gutter and the backdrop for `text`, marking `marks`: line (1-based) → list of
 *  { severity, column, endColumn, label } (columns 1-based, in characters, end exclusive). */
function paintEditor(text, marks = new Map()) {
  const lines = text.split('\n');
  const gutter = [];
  const back = [];
  for (let i = 0; i < lines.length; i++) {
    const line = i + 1;
    const here = marks.get(line) ?? [];
    const severity = here.some((m) => m.severity === 'error') ? 'error' : here.length ? 'warning' : '';
    const title = here.map((m) => m.label).join('\n');
    gutter.push(`<div class="${severity}"${title ? ` title="${escapeHtml(title)}"` : ''}>${line}</div>`);
    const chars = Array.from(lines[i]);
    let html = '';
    if (here.length) {
      // Underline the first mark's span on this line (characters, end exclusive; at least one).
      const m = here.find((x) => x.severity === severity) ?? here[0];
      const from = Math.min(Math.max(m.column - 1, 0), chars.length);
      let to = m.endColumn && m.endColumn > m.column ? m.endColumn - 1 : from + 1;
      to = Math.min(Math.max(to, from), chars.length);
      const pad = to === from ? ' ' : '';
      html =
        escapeHtml(chars.slice(0, from).join('')) +
        `<mark class="${m.severity}">${escapeHtml(chars.slice(from, to).join('')) || pad}</mark>` +
        escapeHtml(chars.slice(to).join(''));
      const more = here.length > 1 ? ` (+${here.length - 1} more)` : '';
      html += `<span class="inline ${severity}">${escapeHtml(here[0].label)}${more}</span>`;
    } else {
      html = escapeHtml(lines[i]);
    }
    back.push(`<div class="line ${severity}" data-line="${line}">${html || ' '}</div>`);
  }
  ui.gutter.innerHTML = gutter.join('');
  // Room below the last line, so the backdrop can scroll as far as the textarea.
  ui.backdrop.innerHTML = back.join('') + '<div style="height: 40px"></div>';
  syncScroll();
}

function syncScroll() {
  ui.backdrop.scrollTop = ui.source.scrollTop;
  ui.backdrop.scrollLeft = ui.source.scrollLeft;
  ui.gutter.style.transform = `translateY(${-ui.source.scrollTop}px)`;
}

/** The UTF-16 offset of (line, column) in `text` (1-based; column in characters). */
function offsetOf(text, line, column) {
  let at = 0;
  for (let l = 1; l < line; l++) {
    const nl = text.indexOf('\n', at);
    if (nl < 0) return text.length;
    at = nl + 1;
  }
  const end = text.indexOf('\n', at) < 0 ? text.length : text.indexOf('\n', at);
  const chars = Array.from(text.slice(at, end)).slice(0, Math.max(column - 1, 0));
  return at + chars.join('').length;
}

function reveal(line, column, endColumn) {
  const text = ui.source.value;
  const from = offsetOf(text, line, column);
  const to = endColumn ? offsetOf(text, line, endColumn) : from;
  ui.source.focus();
  ui.source.setSelectionRange(from, Math.max(from, to));
  ui.source.scrollTop = Math.max(0, (line - 4) * LINE_HEIGHT);
  syncScroll();
}

ui.source.addEventListener('scroll', syncScroll);
ui.source.addEventListener('input', () => {
  files.set(entry, ui.source.value);
  paintEditor(ui.source.value, marksOf(state.diagnostics));
  scheduleCheck();
});
ui.source.addEventListener('keydown', (e) => {
  if (e.key === 'Tab' && !e.shiftKey && !e.ctrlKey && !e.altKey && !e.metaKey) {
    e.preventDefault();
    document.execCommand('insertText', false, '    ');
  }
});

// ---- checking and compiling ----------------------------------------------------------------

/** Line marks of the diagnostics in the edited file (while the user types, those of the last
 *  check stay on their lines until the next check, 150 ms later, replaces them). */
function marksOf(diagnostics) {
  const marks = new Map();
  for (const d of diagnostics) {
    if (d.file !== entry || !Number.isInteger(d.line)) continue;
    const list = marks.get(d.line) ?? [];
    list.push({
      severity: d.severity === 'error' ? 'error' : 'warning',
      column: d.column ?? 1,
      endColumn: d.end_line === d.line ? d.end_column : null,
      label: `${d.severity}${d.code ? `[${d.code}]` : ''}: ${d.message}`,
    });
    marks.set(d.line, list);
  }
  return marks;
}

function showDiagnostics(diagnostics) {
  state.diagnostics = diagnostics;
  paintEditor(ui.source.value, marksOf(diagnostics));
  ui.diagnostics.replaceChildren(
    ...diagnostics.map((d) => {
      const li = document.createElement('li');
      li.className = d.severity === 'error' ? 'error' : 'warning';
      li.dataset.line = d.line ?? '';
      const where = d.file ? `${d.file === entry ? d.file.split('/').pop() : d.file}:${d.line}:${d.column}` : '';
      li.innerHTML =
        `<span class="where">${escapeHtml(where)}</span> ` +
        `<b>${escapeHtml(d.severity)}${d.code ? `[${escapeHtml(d.code)}]` : ''}</b>: ${escapeHtml(d.message ?? '')}` +
        (d.rendered ? `<pre>${escapeHtml(d.rendered.trimEnd())}</pre>` : '');
      if (d.file === entry && Number.isInteger(d.line)) {
        li.addEventListener('click', () => reveal(d.line, d.column ?? 1, d.end_line === d.line ? d.end_column : null));
      }
      return li;
    }),
  );
}

function setCheckStatus(text, kind) {
  ui.checkStatus.textContent = text;
  ui.checkStatus.className = kind;
}

function scheduleCheck() {
  state.checking = true;
  clearTimeout(debounce);
  debounce = setTimeout(check, 150);
}

function counts(diagnostics) {
  const errors = diagnostics.filter((d) => d.severity === 'error').length;
  const warnings = diagnostics.length - errors;
  const plural = (n, w) => `${n} ${w}${n === 1 ? '' : 's'}`;
  return [errors ? plural(errors, 'error') : '', warnings ? plural(warnings, 'warning') : ''].filter(Boolean).join(', ');
}

function check() {
  state.checking = false;
  state.checks += 1;
  const source = ui.source.value;
  let t0 = performance.now();
  let result;
  try {
    result = compiler.check(allFiles(), [entry]);
  } catch (e) {
    setCheckStatus(`the compiler failed: ${e.message ?? e}`, 'bad');
    state.ok = false;
    return;
  }
  const checkMs = performance.now() - t0;
  if (!result.ok) {
    state.ok = false;
    showDiagnostics(result.diagnostics);
    setCheckStatus(`${counts(result.diagnostics)} (checked in ${checkMs.toFixed(0)} ms)`, 'bad');
    showOverlay('the source has errors: this is the last good image');
    return;
  }
  t0 = performance.now();
  let compiled;
  try {
    compiled = compiler.compile(allFiles(), entry, { scene: state.example.scene });
  } catch (e) {
    setCheckStatus(`the compiler failed: ${e.message ?? e}`, 'bad');
    state.ok = false;
    return;
  }
  const compileMs = performance.now() - t0;
  state.ok = compiled.ok;
  showDiagnostics(compiled.diagnostics);
  const timing = `checked in ${checkMs.toFixed(0)} ms, compiled in ${compileMs.toFixed(0)} ms`;
  state.compileMs.push(+(checkMs + compileMs).toFixed(2));
  if (!compiled.ok) {
    setCheckStatus(`${counts(compiled.diagnostics) || 'compile failed'} (${timing})\n${compiled.rendered}`, 'bad');
    showOverlay('the source has errors: this is the last good image');
    return;
  }
  const kernels = Object.keys(compiled.wgsl);
  const bytes = kernels.reduce((n, k) => n + compiled.wgsl[k].length, 0);
  const warn = counts(compiled.diagnostics);
  setCheckStatus(
    `ok${warn ? ` (${warn})` : ''}: scene ${compiled.scene}, ${kernels.length} kernel${kernels.length === 1 ? '' : 's'}, ` +
      `${(bytes / 1024).toFixed(0)} KiB of WGSL (${timing})`,
    'ok',
  );
  showWgsl(compiled);
  // A new renderer for a new source; the same source (an error typed and undone) keeps its image.
  if ((job?.source ?? state.renderedSource) !== source || state.renderError) startRender(source).catch(fatal);
  else showOverlay(null);
}

function showWgsl(compiled) {
  const keep = ui.wgslPick.value;
  const texts = { ...compiled.wgsl };
  if (compiled.manifest) texts['manifest.json'] = compiled.manifest;
  ui.wgslPick.replaceChildren(
    ...Object.keys(texts).map((k) => {
      const o = document.createElement('option');
      o.value = k;
      o.textContent = k === 'manifest.json' ? k : `${k}.wgsl`;
      return o;
    }),
  );
  if (keep in texts) ui.wgslPick.value = keep;
  const show = () => (ui.wgsl.textContent = texts[ui.wgslPick.value] ?? '');
  ui.wgslPick.onchange = show;
  show();
}

// ---- rendering -----------------------------------------------------------------------------

function showOverlay(text) {
  ui.overlay.hidden = !text;
  ui.overlay.textContent = text ?? '';
}

function setRenderStatus(text, bad = false) {
  ui.renderStatus.textContent = text;
  ui.renderStatus.className = bad ? 'bad' : '';
}

function nextFrame() {
  return new Promise((resolve) => requestAnimationFrame(() => resolve()));
}

function stopRender() {
  loads += 1; // a renderer still loading is discarded when it arrives
  state.loading = false;
  if (!job) return;
  job.cancelled = true;
  if (!job.running) job.renderer?.free();
  job = null;
  state.rendering = false;
}

/** The example's files, its assets fetched so far and the dropped files (in its folder). */
function allFiles() {
  const all = new Map([...files, ...assets]);
  for (const [name, bytes] of dropped) all.set(`examples/${state.example.name}/${name}`, bytes);
  return all;
}

/** pkg.loadRenderer's fetchFile: the bytes of `path` (confined by rtc to the scene's folder),
 * from a dropped file or the URL next to the page; null when there is none. */
async function fetchAsset(path) {
  const folder = `examples/${state.example.name}/`;
  if (path.startsWith(folder) && dropped.has(path.slice(folder.length))) return dropped.get(path.slice(folder.length));
  if (assets.has(path)) return assets.get(path);
  const url = `../pkg/${path.split('/').map(encodeURIComponent).join('/')}`;
  const res = await fetch(url);
  if (!res.ok) return null;
  const bytes = new Uint8Array(await res.arrayBuffer());
  assets.set(path, bytes);
  state.fetched.push(path);
  return bytes;
}

async function startRender(source) {
  if (!state.gpu) {
    setRenderStatus(state.gpuError ?? 'waiting for WebGPU…', !!state.gpuError);
    return;
  }
  // The user's camera carries over to the new renderer (as in `rtc view`) if they moved it and the
  // scene's camera can still move; otherwise the new scene's own camera.
  const keptView = job?.canOrbit && job.moved ? job.renderer.view : null;
  stopRender();
  const load = ++loads;
  const ex = examples.find((e) => e.name === state.example.name);
  const scale = Number(ui.scale.value) || 1;
  let renderer;
  const t0 = performance.now();
  state.loading = true;
  try {
    // The scene's size first, then the chosen fraction of it (a second renderer, rarely).
    const options = { scene: state.example.scene };
    renderer = await pkg.loadRenderer(allFiles(), entry, options, fetchAsset);
    if (scale !== 1 && load === loads) {
      const [w, h] = [renderer.width, renderer.height].map((n) => Math.max(1, Math.round(n * scale)));
      renderer.free();
      renderer = await pkg.loadRenderer(allFiles(), entry, { ...options, width: w, height: h }, fetchAsset);
    }
  } catch (e) {
    if (load !== loads) return;
    state.loading = false;
    const why = e.message ?? String(e);
    state.renderError = why;
    const hint = ex?.noRender ? `\nKnown: ${ex.noRender}.` : '';
    setRenderStatus(`the renderer could not start:\n${why}${hint}`, true);
    showOverlay(state.renderedSource ? 'this is the last good image' : null);
    return;
  }
  if (load !== loads) {
    // A newer edit (or example) asked for its own renderer while this one loaded.
    renderer.free();
    return;
  }
  state.loading = false;
  state.renders += 1;
  state.renderError = null;
  const setupMs = performance.now() - t0;
  setRenderStatus(`renderer ready in ${setupMs.toFixed(0)} ms (compile, assets, pipelines, BVH, upload)`);
  job = { renderer, source, cancelled: false, running: false, setupMs, first: true, canOrbit: renderer.canOrbit, moved: false };
  clearMoves();
  if (keptView && job.canOrbit) {
    renderer.setView(keptView.position, keptView.lookAt);
    job.moved = true;
  }
  state.view = job.canOrbit ? renderer.view : null;
  ui.cameraHint.hidden = !job.canOrbit;
  runJob(job);
}

function targetSpp() {
  const n = Math.floor(Number(ui.target.value));
  return Number.isFinite(n) && n >= 1 ? Math.min(n, 65536) : 1;
}

async function runJob(j) {
  if (j.running) return;
  j.running = true;
  state.rendering = true;
  const { renderer } = j;
  const [w, h] = [renderer.width, renderer.height];
  const perPass = renderer.samplesPerPass();
  try {
    while (!j.cancelled) {
      state.targetSpp = targetSpp();
      if (moves.any) applyMoves(j);
      if (!j.first && state.spp >= state.targetSpp) break;
      await nextFrame();
      if (j.cancelled) break;
      const t0 = performance.now();
      const stats = renderer.accumulate(1);
      const rgba = await renderer.readRgba8();
      const ms = performance.now() - t0;
      if (j.cancelled) break;
      if (j.first) {
        ui.canvas.width = w;
        ui.canvas.height = h;
        // Small images are shown enlarged by a whole factor (pixelated), to at least 320 px wide.
        const zoom = Math.max(1, Math.ceil(320 / w));
        ui.canvas.style.width = `${w * zoom}px`;
        j.first = false;
      }
      ui.canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.buffer, rgba.byteOffset, rgba.length), w, h), 0, 0);
      state.renderedSource = j.source;
      state.size = [w, h];
      state.spp = stats.accumulatedSamples;
      state.frameMs = ms;
      showOverlay(state.ok === false ? 'the source has errors: this is the last good image' : null);
      const raysPerS = (w * h * perPass) / (ms / 1000);
      ui.stats.textContent =
        `${state.spp} / ${state.targetSpp} spp · ${w}×${h} · ${ms.toFixed(1)} ms per pass (with read-back) · ` +
        `${(raysPerS / 1e6).toFixed(2)} M camera rays/s`;
      for (const warning of stats.warnings ?? []) console.warn(`rtc: ${warning}`);
    }
  } catch (e) {
    const why = e.message ?? String(e);
    state.renderError = why;
    setRenderStatus(`rendering failed:\n${why}`, true);
  } finally {
    j.running = false;
    if (j.cancelled) j.renderer.free();
    if (job === j) state.rendering = false;
  }
}

// ---- the camera: drag to orbit, shift- or right-drag to pan, wheel to zoom, double-click to reset
// (as in `rtc view`). Moves are gathered here and applied by the render loop before its next pass
// (the renderer is busy while a read-back is pending); each batch restarts the accumulation.

const moves = { yaw: 0, pitch: 0, dx: 0, dy: 0, zoom: 1, reset: false, any: false };

function clearMoves() {
  Object.assign(moves, { yaw: 0, pitch: 0, dx: 0, dy: 0, zoom: 1, reset: false, any: false });
}

function queueMove(change) {
  if (!job?.canOrbit) return;
  change(moves);
  moves.any = true;
  if (!job.running) runJob(job);
}

function applyMoves(j) {
  const { renderer } = j;
  const m = { ...moves };
  clearMoves();
  if (m.reset) renderer.resetView();
  if (m.yaw || m.pitch) renderer.orbit(m.yaw, m.pitch);
  if (m.dx || m.dy) renderer.pan(m.dx, m.dy);
  if (m.zoom !== 1) renderer.zoom(m.zoom);
  j.moved = !m.reset || !!(m.yaw || m.pitch || m.dx || m.dy || m.zoom !== 1);
  state.view = renderer.view;
  state.spp = 0;
  state.cameraMoves += 1;
}

let drag = null;
ui.canvas.addEventListener('pointerdown', (e) => {
  if (!job?.canOrbit) return;
  drag = { x: e.clientX, y: e.clientY, pan: e.button !== 0 || e.shiftKey };
  ui.canvas.setPointerCapture(e.pointerId);
  e.preventDefault();
});
ui.canvas.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const [dx, dy] = [e.clientX - drag.x, e.clientY - drag.y];
  [drag.x, drag.y] = [e.clientX, e.clientY];
  const pan = drag.pan;
  queueMove((m) => {
    if (pan) {
      m.dx += dx * 0.002;
      m.dy += dy * 0.002;
    } else {
      m.yaw += dx * 0.01;
      m.pitch += dy * 0.01;
    }
  });
});
for (const type of ['pointerup', 'pointercancel']) ui.canvas.addEventListener(type, () => (drag = null));
ui.canvas.addEventListener('contextmenu', (e) => e.preventDefault());
ui.canvas.addEventListener(
  'wheel',
  (e) => {
    if (!job?.canOrbit) return;
    e.preventDefault();
    const lines = e.deltaMode === 0 ? e.deltaY / 100 : e.deltaY;
    queueMove((m) => (m.zoom *= 0.9 ** -lines));
  },
  { passive: false },
);
ui.canvas.addEventListener('dblclick', () =>
  queueMove((m) => {
    Object.assign(m, { yaw: 0, pitch: 0, dx: 0, dy: 0, zoom: 1 });
    m.reset = true;
  }),
);

ui.target.addEventListener('change', () => {
  state.targetSpp = targetSpp();
  const url = new URL(location.href);
  url.searchParams.set('spp', String(state.targetSpp));
  history.replaceState(null, '', url);
  if (job && !job.running && state.spp < state.targetSpp) runJob(job);
});
ui.scale.addEventListener('change', () => {
  const url = new URL(location.href);
  url.searchParams.set('scale', ui.scale.value);
  history.replaceState(null, '', url);
  if (state.ok && state.gpu) startRender(ui.source.value).catch(fatal);
});

// ---- dropped files: they join the example's folder under their names, so the scene can name them
// (`load_mesh("model.obj")`, `load_image("wood.png")`, `model "car.glb"` with its .bin and images).

async function dropFiles(list) {
  if (!list.length) return;
  for (const f of list) dropped.set(f.name, new Uint8Array(await f.arrayBuffer()));
  state.dropped = [...dropped.keys()];
  ui.dropped.textContent = `dropped: ${state.dropped.join(', ')} (in the example's folder)`;
  if (state.ok && state.gpu) startRender(ui.source.value).catch(fatal);
  else scheduleCheck();
}
document.addEventListener('dragover', (e) => e.preventDefault());
document.addEventListener('drop', (e) => {
  e.preventDefault();
  dropFiles([...(e.dataTransfer?.files ?? [])]).catch(fatal);
});
window.rtcPlayground.dropFiles = dropFiles;

// ---- examples ------------------------------------------------------------------------------

async function loadExample(value) {
  const [name, file] = value.split('/');
  const ex = examples.find((e) => e.name === name);
  const ent = ex?.entries.find((e) => e.file === file) ?? ex?.entries[0];
  if (!ex || !ent) return;
  stopRender();
  const loaded = new Map();
  await Promise.all(
    ex.files.map(async (f) => {
      const res = await fetch(`../pkg/examples/${ex.name}/${f}`);
      if (!res.ok) throw new Error(`../pkg/examples/${ex.name}/${f}: HTTP ${res.status}`);
      loaded.set(`examples/${ex.name}/${f}`, await res.text());
    }),
  );
  files = loaded;
  // The assets its sources name, fetched now so that the first check links a `model` from its
  // contents; anything else (a glTF's buffers and images) is fetched when the renderer asks.
  assets = new Map();
  state.example = { name: ex.name, file: ent.file, scene: ent.scene };
  await Promise.all(ex.assets.map((a) => fetchAsset(`examples/${ex.name}/${a}`)));
  entry = `examples/${ex.name}/${ent.file}`;
  state.example = { name: ex.name, file: ent.file, scene: ent.scene };
  state.renderedSource = null;
  state.renderError = null;
  original = files.get(entry);
  ui.source.value = original;
  ui.source.scrollTop = 0;
  ui.example.value = `${ex.name}/${ent.file}`;
  const url = new URL(location.href);
  url.searchParams.set('example', `${ex.name}/${ent.file}`);
  history.replaceState(null, '', url);
  if (ex.noRender) {
    setRenderStatus(`${ex.name}: ${ex.noRender}; checking and compiling work.`, true);
  } else {
    setRenderStatus('');
  }
  showDiagnostics([]);
  check();
}

function fillPicker() {
  const renders = document.createElement('optgroup');
  renders.label = 'render in the browser';
  const checkOnly = document.createElement('optgroup');
  checkOnly.label = 'check and compile only';
  for (const ex of examples) {
    for (const ent of ex.entries) {
      const o = document.createElement('option');
      o.value = `${ex.name}/${ent.file}`;
      const label = ex.entries.length > 1 ? `${ex.name}/${ent.file}` : ex.name;
      if (ex.noRender) {
        o.textContent = `${label} (cannot render here)`;
        checkOnly.append(o);
      } else {
        o.textContent = label;
        renders.append(o);
      }
    }
  }
  ui.example.replaceChildren(renders, checkOnly);
  ui.example.disabled = false;
}

ui.example.addEventListener('change', () => loadExample(ui.example.value).catch(fatal));
ui.revert.addEventListener('click', () => {
  ui.source.value = original;
  files.set(entry, original);
  scheduleCheck();
});

// ---- start ---------------------------------------------------------------------------------

function fatal(e) {
  setCheckStatus(`${e.message ?? e}`, 'bad');
  console.error(e);
}

async function initWebGpu() {
  if (!('gpu' in navigator) || !navigator.gpu) {
    state.gpuError =
      'The renderer needs WebGPU, which this browser does not offer (no navigator.gpu): checking and ' +
      'compiling work. Try a recent Chrome or Edge (Chromium on Linux: --enable-unsafe-webgpu), or ' +
      'Safari 26 / Firefox 141+ where WebGPU is on.';
  } else if (typeof pkg.initGpu !== 'function') {
    state.gpuError = 'web/pkg was built without the renderer: run `bash web/build.sh --renderer`.';
  } else {
    try {
      state.gpu = await pkg.initGpu();
      // wgpu's description may lack the name on the web; the browser's adapter info says more.
      const info = (await navigator.gpu.requestAdapter())?.info;
      const more = [info?.vendor, info?.architecture, info?.description].filter(Boolean).join(' ');
      if (more) state.gpu = `${state.gpu.trim()} [${more}]`;
    } catch (e) {
      state.gpuError = `The renderer needs WebGPU, and no adapter was found: ${e.message ?? e}`;
    }
  }
  ui.gpu.textContent = state.gpu ? `WebGPU: ${state.gpu}` : 'WebGPU: not available';
  ui.gpu.title = state.gpuError ?? '';
  if (!state.gpu) setRenderStatus(state.gpuError, true);
}

async function main() {
  const params = new URL(location.href).searchParams;
  if (params.get('spp')) ui.target.value = params.get('spp');
  if (params.get('scale')) ui.scale.value = params.get('scale');
  state.targetSpp = targetSpp();
  try {
    pkg = await import('../pkg/web/rtc_web.js');
    await pkg.default();
  } catch (e) {
    fatal(new Error(`could not load ../pkg/web/rtc_web.js (build it with \`bash web/build.sh --renderer\`): ${e.message ?? e}`));
    return;
  }
  compiler = new pkg.WebCompiler();
  const res = await fetch('../pkg/examples.json');
  if (!res.ok) throw new Error(`../pkg/examples.json: HTTP ${res.status} (run bash web/build.sh)`);
  examples = await res.json();
  fillPicker();
  await initWebGpu();
  const wanted = params.get('example') ?? 'hello/scene.rt';
  const [name, file] = wanted.split('/');
  const ex = examples.find((e) => e.name === name) ?? examples.find((e) => e.name === 'hello') ?? examples[0];
  await loadExample(`${ex.name}/${file ?? ex.entries[0].file}`);
  state.ready = true;
}

main().catch(fatal);
