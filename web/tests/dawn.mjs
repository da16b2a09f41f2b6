// web/tests/dawn.mjs: every kernel's WGSL checked by Dawn (Chromium's WebGPU, the npm package
// `webgpu`) at WebGPU's default limits.
//
//   node web/tests/dawn.mjs            (after bash web/build.sh; npm ci in web/)
//
// The WGSL comes from the compiler in WebAssembly (web/pkg/node, byte-identical to `rtc compile`:
// web/tests/compiler.mjs). Kernels compiled:
// - every scene of examples/, runtime/tests/scenes/ and tests/scenes/ with the scene's execution
//   model, and the examples' again with the wavefront model (its stage kernels; the test scenes'
//   too with RTC_DAWN_ALL=1: lavapipe compiling every pipeline is most of the time this takes);
// - one generated scene that imports every standard-library module (kernel and prelude aside) and
//   is compiled with `allPrograms`, so every standard-library program is in some kernel.
// For each distinct WGSL text: `createShaderModule`, `getCompilationInfo` (warnings are listed,
// errors fail), and `createComputePipeline` for every `@compute` entry point, inside validation
// and internal error scopes (any error fails). The adapter and device are requested with no
// limits raised. The coverage (standard-library programs linked into some kernel) is printed.
// With no adapter at all, the check is skipped with a message (exit 0); RTC_DAWN_REQUIRED=1 makes
// that a failure.
import { create, globals } from 'webgpu';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { createHash } from 'node:crypto';
import { repo, loadCompiler, filesUnder, scenes } from './files.mjs';

Object.assign(globalThis, globals);
const started = performance.now();
const { WebCompiler } = loadCompiler();
const compiler = new WebCompiler();

// Every file a scene may read: sources, registries and glTF files of the three scene folders.
const files = new Map();
for (const dir of ['examples', 'runtime/tests/scenes', 'tests/scenes']) filesUnder(dir, files);

// The kernels to check, by WGSL text.
const kernels = new Map(); // hash -> { code, uses: [label] }
const programs = new Map(); // program key -> first label
const failedCompiles = [];
function add(label, out) {
  if (!out.ok) {
    failedCompiles.push(`${label}: ${out.rendered.split('\n')[0]}`);
    return;
  }
  for (const [name, code] of Object.entries(out.wgsl)) {
    const hash = createHash('sha256').update(code).digest('hex');
    const k = kernels.get(hash) ?? { code, uses: [] };
    k.uses.push(`${label} ${name}`);
    kernels.set(hash, k);
  }
  const manifest = JSON.parse(out.manifest);
  for (const p of manifest.programs ?? []) {
    if (!programs.has(p.name)) programs.set(p.name, label);
  }
}

for (const { file, scene } of scenes()) {
  add(`${file}#${scene}`, compiler.compile(files, file, { scene }));
  if (file.startsWith('examples/') || process.env.RTC_DAWN_ALL === '1') {
    add(`${file}#${scene} (wavefront)`, compiler.compile(files, file, { scene, exec: 'wavefront' }));
  }
}
const fromScenes = new Set(programs.keys());

// Every standard-library module, imported by a copy of examples/hello's scene.
const stdModules = WebCompiler.stdlibFiles().filter(
  (p) => p !== 'prelude.rt' && !p.startsWith('kernel/'),
);
const hello = readFileSync(join(repo, 'examples/hello/scene.rt'), 'utf8');
const allStd = stdModules.map((p) => `import "std/${p}";`).join('\n') + '\n' + hello;
const allFiles = new Map(files);
allFiles.set('examples/hello/all_std.rt', allStd);
add('every std module (allPrograms)', compiler.compile(allFiles, 'examples/hello/all_std.rt', { allPrograms: true }));
add(
  'every std module (allPrograms, wavefront)',
  compiler.compile(allFiles, 'examples/hello/all_std.rt', { allPrograms: true, exec: 'wavefront' }),
);
const compiledIn = ((performance.now() - started) / 1000).toFixed(1);

// The standard library's programs: every function under a `@kind` attribute (outside kernel/).
const stdPrograms = [];
for (const p of stdModules) {
  const text = readFileSync(join(repo, 'stdlib', p), 'utf8');
  for (const m of text.matchAll(/^@([a-z_]+)[^\n]*\n(?:\s*\/\/[^\n]*\n)*\s*fn\s+([A-Za-z_][A-Za-z0-9_]*)/gm)) {
    stdPrograms.push({ module: `std/${p}`, kind: m[1], name: m[2] });
  }
}
const missing = stdPrograms.filter((p) => !programs.has(p.name));
console.log(`compiled ${scenes().length} scenes (+ 1 generated) in ${compiledIn} s: ${kernels.size} distinct kernels`);
console.log(`standard-library programs in some kernel: ${stdPrograms.length - missing.length} of ${stdPrograms.length} ` +
  `(${stdPrograms.filter((p) => fromScenes.has(p.name)).length} by the scenes alone):`);
for (const p of stdPrograms) {
  const by = fromScenes.has(p.name) ? 'scene    ' : programs.has(p.name) ? 'generated' : 'MISSING  ';
  console.log(`  ${by} ${p.module} @${p.kind} ${p.name}`);
}
if (failedCompiles.length) {
  console.log(`not compiled (compiler diagnostics, not a WGSL check): ${failedCompiles.length}`);
  for (const f of failedCompiles) console.log(`  ${f}`);
}

const gpu = create([]);
const adapter = await gpu.requestAdapter();
if (!adapter) {
  const msg = 'no WebGPU adapter (Dawn found no Vulkan device: is mesa-vulkan-drivers installed?)';
  if (process.env.RTC_DAWN_REQUIRED === '1') {
    console.error(`error: ${msg}`);
    process.exit(1);
  }
  console.log(`skipped: ${msg}`);
  process.exit(0);
}
const info = adapter.info;
console.log(`adapter: ${info.vendor} ${info.architecture} ${info.device} ${info.description}`);
const device = await adapter.requestDevice(); // no requiredLimits: WebGPU's defaults
console.log(`limits: ${device.limits.maxStorageBuffersPerShaderStage} storage buffers per stage, ` +
  `${device.limits.maxStorageBufferBindingSize} bytes per storage binding`);

let errors = 0;
let warnings = 0;
let pipelines = 0;
const checkStart = performance.now();
for (const { code, uses } of kernels.values()) {
  const label = uses[0] + (uses.length > 1 ? ` (+${uses.length - 1} identical)` : '');
  device.pushErrorScope('internal');
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ code, label });
  const compilation = await module.getCompilationInfo();
  for (const m of compilation.messages) {
    const where = `${label}:${m.lineNum}:${m.linePos}`;
    if (m.type === 'error') {
      errors += 1;
      console.log(`error: ${where}: ${m.message}`);
    } else {
      warnings += 1;
      console.log(`${m.type}: ${where}: ${m.message}`);
    }
  }
  for (const scope of ['validation', 'internal']) {
    const e = await device.popErrorScope();
    if (e) {
      errors += 1;
      console.log(`error: ${label}: createShaderModule (${scope}): ${e.message}`);
    }
  }
  const entries = [...code.matchAll(/@compute\s+@workgroup_size\([^)]*\)\s*fn\s+([A-Za-z_][A-Za-z0-9_]*)/g)].map((m) => m[1]);
  if (entries.length === 0) {
    errors += 1;
    console.log(`error: ${label}: no @compute entry point found`);
  }
  for (const entryPoint of entries) {
    device.pushErrorScope('internal');
    device.pushErrorScope('validation');
    device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint }, label: `${label} ${entryPoint}` });
    pipelines += 1;
    for (const scope of ['validation', 'internal']) {
      const e = await device.popErrorScope();
      if (e) {
        errors += 1;
        console.log(`error: ${label}: createComputePipeline(${entryPoint}) (${scope}): ${e.message}`);
      }
    }
  }
}
device.destroy();
const took = ((performance.now() - checkStart) / 1000).toFixed(1);
console.log(`Dawn: ${kernels.size} shader modules, ${pipelines} compute pipelines in ${took} s: ` +
  `${errors} errors, ${warnings} warnings`);
if (missing.length > 0) console.log(`error: ${missing.length} standard-library programs are in no kernel`);
process.exit(errors > 0 || missing.length > 0 ? 1 : 0);
