// web/tests/render.mjs: the renderer in WebAssembly (rtc-runtime on wgpu's WebGPU backend) on
// Dawn (the npm package `webgpu`, on lavapipe), against `rtc render` of the same scene, size and
// samples: PSNR ≥ 40 dB over the 8-bit sRGB pixels.
//
//   bash web/build.sh --renderer && cargo build -p rtc && node web/tests/render.mjs
//
// wgpu's web backend finds the GPU through `globalThis.Window` (any defined value: the global is
// then taken for a window) and `globalThis.navigator.gpu`, so both are set here; the package's
// `globals` (GPUBufferUsage, GPUValidationError, …) are what the browser would define.
// With no adapter at all, the test is skipped with a message (exit 0); RTC_DAWN_REQUIRED=1 makes
// that a failure.
import { create, globals } from 'webgpu';
import { execFileSync } from 'node:child_process';
import { readFileSync, mkdtempSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { repo, loadCompiler, filesUnder } from './files.mjs';
import { decodePng, psnrRgbaRgb } from './png.mjs';

Object.assign(globalThis, globals);
globalThis.Window ??= class Window {};
Object.defineProperty(globalThis, 'navigator', {
  value: { gpu: create([]) },
  configurable: true,
  writable: true,
});

const pkg = loadCompiler();
if (typeof pkg.initGpu !== 'function') {
  throw new Error('web/pkg/node has no renderer: build it with `bash web/build.sh --renderer`');
}
let adapter;
try {
  adapter = await pkg.initGpu();
} catch (e) {
  if (process.env.RTC_DAWN_REQUIRED === '1') throw e;
  console.log(`skipped: no WebGPU device (${e.message ?? e})`);
  process.exit(0);
}
console.log(`adapter: ${adapter}`);

const rtc = join(repo, 'target', 'debug', 'rtc');
const cases = [
  { scene: 'examples/hello/scene.rt', width: 64, height: 48, samples: 4 },
  { scene: 'examples/cornell_box/scene.rt', width: 48, height: 48, samples: 2 },
];
let failed = false;
for (const { scene, width, height, samples } of cases) {
  const dir = scene.slice(0, scene.lastIndexOf('/'));
  const renderer = new pkg.WebRenderer(filesUnder(dir), scene, { width, height, samples });
  const passes = Math.ceil(samples / renderer.samplesPerPass());
  const stats = renderer.accumulate(passes);
  const rgba = await renderer.readRgba8();

  const tmp = mkdtempSync(join(tmpdir(), 'rtc-web-render-'));
  const png = join(tmp, 'native.png');
  execFileSync(rtc, ['render', scene, '--size', `${width}x${height}`, '--spp', `${samples}`, '-o', png], {
    cwd: repo,
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  const native = decodePng(readFileSync(png));
  rmSync(tmp, { recursive: true, force: true });

  if (native.width !== width || native.height !== height || rgba.length !== width * height * 4) {
    console.log(`FAIL ${scene}: sizes differ`);
    failed = true;
    continue;
  }
  const { psnr, differing } = psnrRgbaRgb(rgba, native.rgb, width * height);
  const ok = psnr >= 40;
  if (!ok) failed = true;
  // A leading newline: Dawn's warnings (printed by wgpu) end without one.
  console.log(
    `\n${ok ? 'ok  ' : 'FAIL'} ${scene} ${width}x${height} ${samples} spp (${stats.passes} passes, ` +
      `${stats.renderMs.toFixed(1)} ms submit): PSNR ${psnr.toFixed(2)} dB, ${differing} pixels differ`,
  );
}
process.exit(failed ? 1 : 0);
