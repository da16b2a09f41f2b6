// docs/bench/web_frames.mjs: frames of the renderer in WebAssembly (web/pkg/node: rtc-runtime on
// wgpu's WebGPU backend) on Dawn (npm `webgpu`), against native `rtc render` on the same adapter
// (lavapipe: Dawn's Vulkan backend and wgpu's both drive it), per scene at its own size.
//
//   bash docs/bench/web_frames.sh [PASSES]    (builds what is missing; default 32 passes)
//
// Per scene: the web renderer is created (its pipelines compiled) and one pass rendered and read
// back, not timed; then PASSES passes the way the playground draws them, `accumulate(1)` and
// `await readRgba8()` each (ms per pass with the read-back, and frames per second), then PASSES
// passes submitted together and read back once (ms per pass of GPU work alone). Native: `rtc
// render --spp PASSES×samples-per-pass`, its `render` line (every pass and one read-back) over
// PASSES. Prints one JSON line per scene.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const repo = join(fileURLToPath(import.meta.url), '..', '..', '..');
// npm's `webgpu` lives in web/node_modules (web/package.json), not beside this script.
const { create, globals } = createRequire(join(repo, 'web/package.json'))('webgpu');
const { filesUnder } = await import(join(repo, 'web/tests/files.mjs'));
Object.assign(globalThis, globals);
globalThis.Window ??= class Window {};
Object.defineProperty(globalThis, 'navigator', { value: { gpu: create([]) }, configurable: true, writable: true });

const passes = Number(process.argv[2] ?? 32);
const scenes = process.argv.slice(3).length ? process.argv.slice(3) : ['examples/hello/scene.rt', 'examples/cornell_box/scene.rt'];
const pkg = createRequire(import.meta.url)(join(repo, 'web/pkg/node/rtc_web.js'));
const adapter = await pkg.initGpu();
const rtc = process.env.RTC_BIN ?? join(repo, 'target/release/rtc');

for (const scene of scenes) {
  const dir = scene.slice(0, scene.lastIndexOf('/'));
  const t0 = performance.now();
  const renderer = new pkg.WebRenderer(filesUnder(dir), scene, {});
  renderer.accumulate(1);
  await renderer.readRgba8();
  const setupMs = performance.now() - t0;
  const perPass = renderer.samplesPerPass();
  const [width, height] = [renderer.width, renderer.height];

  renderer.resetAccumulation();
  let t = performance.now();
  for (let i = 0; i < passes; i += 1) {
    renderer.accumulate(1);
    await renderer.readRgba8();
  }
  const pageMs = (performance.now() - t) / passes;

  renderer.resetAccumulation();
  t = performance.now();
  renderer.accumulate(passes);
  await renderer.readRgba8();
  const batchMs = (performance.now() - t) / passes;
  renderer.free();

  const tmp = mkdtempSync(join(tmpdir(), 'rtc-web-frames-'));
  const run = spawnSync(
    rtc,
    ['render', scene, '--size', `${width}x${height}`, '--spp', `${passes * perPass}`, '-o', join(tmp, 'n.png'), '--color', 'never'],
    { cwd: repo, encoding: 'utf8' },
  );
  if (run.status !== 0) throw new Error(`rtc render ${scene} failed:\n${run.stderr}`);
  const out = run.stdout + run.stderr;
  rmSync(tmp, { recursive: true, force: true });
  const render = /^\s*render\s+([\d.]+) ms/m.exec(out);
  const nativeMs = render ? Number(render[1]) / passes : null;
  console.log(
    JSON.stringify({
      scene,
      adapter: adapter.trim(),
      size: `${width}x${height}`,
      samplesPerPass: perPass,
      passes,
      webSetupMs: Math.round(setupMs),
      webMsPerPassWithReadback: +pageMs.toFixed(2),
      webFps: +(1000 / pageMs).toFixed(1),
      webMsPerPassBatched: +batchMs.toFixed(2),
      nativeMsPerPass: nativeMs && +nativeMs.toFixed(2),
      webOverNative: nativeMs && +(batchMs / nativeMs).toFixed(3),
    }),
  );
}
