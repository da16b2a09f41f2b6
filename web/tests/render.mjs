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
import { inflateSync } from 'node:zlib';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { repo, loadCompiler, filesUnder } from './files.mjs';

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

/** 8-bit RGB or RGBA PNG (no interlace) → { width, height, rgb }. */
function decodePng(bytes) {
  let at = 8;
  let width = 0, height = 0, channels = 0;
  const idat = [];
  while (at < bytes.length) {
    const length = bytes.readUInt32BE(at);
    const type = bytes.toString('latin1', at + 4, at + 8);
    const data = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0) throw new Error('expected an 8-bit, non-interlaced PNG');
      channels = { 2: 3, 6: 4 }[data[9]];
      if (!channels) throw new Error(`PNG colour type ${data[9]} not handled`);
    } else if (type === 'IDAT') idat.push(data);
    at += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const out = Buffer.alloc(stride * height);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? out[y * stride + x - channels] : 0;
      const b = y > 0 ? out[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? out[(y - 1) * stride + x - channels] : 0;
      const p = a + b - c;
      const pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const paeth = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      const predict = [0, a, b, (a + b) >> 1, paeth][filter];
      out[y * stride + x] = (line[x] + predict) & 0xff;
    }
  }
  const rgb = Buffer.alloc(width * height * 3);
  for (let i = 0; i < width * height; i++) out.copy(rgb, i * 3, i * channels, i * channels + 3);
  return { width, height, rgb };
}

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
  let squared = 0, differing = 0;
  for (let i = 0; i < width * height; i++) {
    let same = true;
    for (let c = 0; c < 3; c++) {
      const d = rgba[i * 4 + c] - native.rgb[i * 3 + c];
      squared += d * d;
      if (d !== 0) same = false;
    }
    if (!same) differing++;
  }
  const mse = squared / (width * height * 3);
  const psnr = mse === 0 ? Infinity : 10 * Math.log10((255 * 255) / mse);
  const ok = psnr >= 40;
  if (!ok) failed = true;
  // A leading newline: Dawn's warnings (printed by wgpu) end without one.
  console.log(
    `\n${ok ? 'ok  ' : 'FAIL'} ${scene} ${width}x${height} ${samples} spp (${stats.passes} passes, ` +
      `${stats.renderMs.toFixed(1)} ms submit): PSNR ${psnr.toFixed(2)} dB, ${differing} pixels differ`,
  );
}
process.exit(failed ? 1 : 0);
