// web/tests/render.mjs: the renderer in WebAssembly (rtc-runtime on wgpu's WebGPU backend) on
// Dawn (the npm package `webgpu`, on lavapipe), against `rtc render` of the same scene, size and
// samples: PSNR ≥ 40 dB over the 8-bit sRGB pixels. Scenes with assets are loaded through
// `loadRenderer`, whose `fetchFile` reads them here from the disk: the files it asks for (OBJ and
// PNG, then a glTF file, then the buffer and image that file names) must be exactly those the scene
// needs, a path leading out of the scene's folder must be refused without being asked for, and a
// missing file must be reported by name. `loadRenderer` also renders custom geometry (examples/
// lights), whose setup reads the bounds kernel's boxes back (awaited).
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
import { readFileSync, mkdtempSync, rmSync, writeFileSync, mkdirSync, copyFileSync } from 'node:fs';
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
const tmp = mkdtempSync(join(tmpdir(), 'rtc-web-render-'));

// A textured glTF triangle whose buffer and image are files beside it (two fetch rounds), in
// tmp/gltf/ with its scene; and tmp/secret.obj, outside that folder.
mkdirSync(join(tmp, 'gltf'));
const corpus = join(repo, 'tests/corpus/gltf/image_missing');
copyFileSync(join(corpus, 'model.gltf'), join(tmp, 'gltf/model.gltf'));
copyFileSync(join(corpus, 'm.bin'), join(tmp, 'gltf/m.bin'));
copyFileSync(join(repo, 'examples/assets/checker.png'), join(tmp, 'gltf/tex.png'));
copyFileSync(join(repo, 'examples/assets/bunny-6k.obj'), join(tmp, 'secret.obj'));
const sceneText = (entry) => `import "std/cameras/pinhole.rt";
import "std/lights/point.rt";
import "std/materials/lambert.rt";
import "std/miss/gradient.rt";
scene fetched {
    settings { width: 48, height: 48, samples: 1 }
    camera Pinhole { position: vec3f(0.5, 0.5, 2.0), look_at: vec3f(0.5, 0.5, 0.0), fov: 50.0 }
    background SkyGradient {}
    light key PointLight { position: vec3f(0.5, 0.5, 1.5), intensity: 4.0 }
    ${entry}
}
`;
writeFileSync(join(tmp, 'gltf/scene.rt'), sceneText('model "model.gltf" {}'));

/** A fetchFile over the folder `root` (paths as the scene's files are named there), recording
 *  what it is asked for. */
function fetchFrom(root, asked) {
  return async (path) => {
    asked.push(path);
    try {
      return new Uint8Array(readFileSync(join(root, path)));
    } catch {
      return null;
    }
  };
}

const cases = [
  { scene: 'examples/hello/scene.rt', width: 64, height: 48, samples: 4 },
  { scene: 'examples/cornell_box/scene.rt', width: 48, height: 48, samples: 2 },
  // OBJ and PNG, fetched in one round.
  { scene: 'examples/shading/scene.rt', width: 48, height: 36, samples: 1, fetched: [['examples/shading/bunny-6k.obj', 'examples/shading/checker.png']] },
  // Custom geometry: the bounds kernel's boxes are read back once at setup, awaited.
  { scene: 'examples/lights/scene.rt', width: 48, height: 36, samples: 1, fetched: [] },
  // The glTF file, then its buffer and image.
  { scene: 'gltf/scene.rt', root: tmp, width: 48, height: 48, samples: 1, fetched: [['gltf/model.gltf'], ['gltf/m.bin', 'gltf/tex.png']] },
];
let failed = false;
for (const { scene, root = repo, width, height, samples, fetched } of cases) {
  const dir = scene.slice(0, scene.lastIndexOf('/'));
  const options = { width, height, samples };
  let renderer;
  if (fetched) {
    const asked = [];
    const files = new Map([[scene, readFileSync(join(root, scene), 'utf8')]]);
    if (root === repo) filesUnder(dir, files);
    for (const f of fetched.flat()) files.delete(f);
    renderer = await pkg.loadRenderer(files, scene, options, fetchFrom(root, asked));
    const want = fetched.flat();
    if (JSON.stringify(asked) !== JSON.stringify(want)) {
      console.log(`FAIL ${scene}: fetchFile was asked for ${JSON.stringify(asked)}, not ${JSON.stringify(want)}`);
      failed = true;
    }
  } else {
    renderer = new pkg.WebRenderer(filesUnder(dir), scene, options);
  }
  const passes = Math.ceil(samples / renderer.samplesPerPass());
  const stats = renderer.accumulate(passes);
  const rgba = await renderer.readRgba8();
  renderer.free();

  const png = join(tmp, 'native.png');
  execFileSync(rtc, ['render', scene, '--size', `${width}x${height}`, '--spp', `${samples}`, '-o', png], {
    cwd: root,
    stdio: ['ignore', 'ignore', 'inherit'],
  });
  const native = decodePng(readFileSync(png));

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
      `${stats.renderMs.toFixed(1)} ms submit${fetched ? `, fetched ${fetched.flat().length} files in ${fetched.length} rounds` : ''}): ` +
      `PSNR ${psnr.toFixed(2)} dB, ${differing} pixels differ`,
  );
}

// Paths out of the scene's folder are refused before anything is fetched; a missing file is
// reported by name.
for (const [entry, expect, wantAsked] of [
  ['object o { geometry: load_mesh("../secret.obj"), material: Lambert {} }', /outside|leads out|E0903/, []],
  ['object o { geometry: load_mesh("sub/../../secret.obj"), material: Lambert {} }', /outside|leads out|E0903/, []],
  ['object o { geometry: load_mesh("gone.obj"), material: Lambert {} }', /gone\.obj/, ['gltf/gone.obj']],
]) {
  const asked = [];
  const files = new Map([['gltf/scene.rt', sceneText(entry)]]);
  let error = null;
  try {
    (await pkg.loadRenderer(files, 'gltf/scene.rt', {}, fetchFrom(tmp, asked))).free();
  } catch (e) {
    error = e.message ?? String(e);
  }
  const ok = error !== null && expect.test(error) && JSON.stringify(asked) === JSON.stringify(wantAsked);
  if (!ok) failed = true;
  console.log(`\n${ok ? 'ok  ' : 'FAIL'} ${entry}: asked for ${JSON.stringify(asked)}; ${error?.split('\n')[0]}`);
}
rmSync(tmp, { recursive: true, force: true });
process.exit(failed ? 1 : 0);
