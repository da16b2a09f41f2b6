// docs/bench/wasm_compile.mjs: edit → WGSL latency of examples/hello in the compiler in
// WebAssembly (web/pkg/node) under Node; run by docs/bench/wasm_compile.sh.
//
// Prints one line of JSON: the first compile with a new compiler (`cold_ms`, includes nothing of
// module loading) and the median and minimum of N compiles after an edit of the scene file.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { repo, loadCompiler } from '../../web/tests/files.mjs';

const n = Number(process.argv[2] ?? 20);
const { WebCompiler } = loadCompiler();
const entry = 'examples/hello/scene.rt';
const scene = readFileSync(join(repo, entry), 'utf8');
const registry = readFileSync(join(repo, 'examples/hello/rtc.registry.json'), 'utf8');
const files = (edit) => ({ [entry]: `${scene}// edit ${edit}\n`, 'examples/hello/rtc.registry.json': registry });
const compiler = new WebCompiler();
let t = performance.now();
const first = compiler.compile(files(0), entry);
const cold = performance.now() - t;
if (!first.ok) throw new Error(first.rendered);
const warm = [];
for (let i = 1; i <= n; i++) {
  t = performance.now();
  const out = compiler.compile(files(i), entry);
  warm.push(performance.now() - t);
  if (!out.ok) throw new Error(out.rendered);
}
warm.sort((a, b) => a - b);
console.log(JSON.stringify({
  cold_ms: +cold.toFixed(2),
  warm_median_ms: +warm[Math.floor(n / 2)].toFixed(2),
  warm_min_ms: +warm[0].toFixed(2),
  iterations: n,
}));
