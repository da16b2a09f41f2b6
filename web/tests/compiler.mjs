// web/tests/compiler.mjs: the compiler in WebAssembly (web/pkg/node) against the native one.
//
//   node web/tests/compiler.mjs        (after bash web/build.sh and cargo build -p rtc)
//
// - examples/hello and examples/cornell_box compiled from in-memory files give byte for byte the
//   WGSL and manifest.json that `target/debug/rtc compile --target wgsl` writes (RTC_BIN overrides
//   the binary);
// - a type error and a syntax error are diagnostics at the right file, line and column, with the
//   rendered text; a missing import is a diagnostic; bad arguments throw (no panic, no abort).
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { repo, loadCompiler, filesUnder } from './files.mjs';

const rtc = process.env.RTC_BIN ?? join(repo, 'target', 'debug', 'rtc');
const { WebCompiler } = loadCompiler();
const compiler = new WebCompiler();
let passed = 0;
function test(name, body) {
  body();
  passed += 1;
  console.log(`ok - ${name}`);
}

for (const example of ['hello', 'cornell_box']) {
  test(`examples/${example}: WGSL and manifest byte-identical to rtc compile`, () => {
    const entry = `examples/${example}/scene.rt`;
    const files = filesUnder(`examples/${example}`);
    const out = compiler.compile(files, entry);
    assert.equal(out.ok, true, out.rendered);
    const dir = mkdtempSync(join(tmpdir(), 'rtc-web-'));
    try {
      const native = spawnSync(rtc, ['compile', entry, '--target', 'wgsl', '--out', dir, '--color', 'never'], {
        cwd: repo,
        encoding: 'utf8',
      });
      assert.equal(native.status, 0, native.stderr);
      const written = readdirSync(dir).sort();
      const wasm = [...Object.keys(out.wgsl).map((k) => `${k}.wgsl`), 'manifest.json'].sort();
      assert.deepEqual(wasm, written);
      for (const name of written) {
        const expected = readFileSync(join(dir, name), 'utf8');
        const got = name === 'manifest.json' ? out.manifest : out.wgsl[name.replace(/\.wgsl$/, '')];
        assert.ok(got === expected, `${entry}: ${name} differs from rtc compile's`);
      }
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
}

test('a type error is located (file, line, column, span) and rendered', () => {
  const text = 'fn f() -> f32 {\n    let x: f32 = 1.0;\n    return true;\n}\n';
  const out = compiler.check({ 'user/bad.rt': text });
  assert.equal(out.ok, false);
  const d = out.diagnostics.find((d) => d.severity === 'error');
  assert.ok(d, out.rendered);
  assert.equal(d.file, 'user/bad.rt');
  assert.equal(d.line, 3);
  assert.equal(d.column, 12);
  assert.equal(text.slice(d.lo, d.hi), 'true');
  assert.match(d.code, /^E\d{4}$/);
  assert.ok(out.rendered.includes('user/bad.rt:3:12'), out.rendered);
});

test('a syntax error in a compile is located, with no WGSL', () => {
  const files = filesUnder('examples/hello');
  const entry = 'examples/hello/scene.rt';
  const broken = files.get(entry).replace('scene ', 'scene scene ');
  files.set(entry, broken);
  const out = compiler.compile(files, entry);
  assert.equal(out.ok, false);
  assert.deepEqual(out.wgsl, {});
  assert.equal(out.manifest, null);
  const d = out.diagnostics[0];
  assert.equal(d.file, entry);
  const line = broken.split('\n').findIndex((l) => l.includes('scene scene')) + 1;
  assert.equal(d.line, line, out.rendered);
});

test('a missing import is a diagnostic', () => {
  const out = compiler.check(new Map([['a.rt', 'import "nowhere.rt";\n']]));
  assert.equal(out.ok, false);
  assert.equal(out.diagnostics[0].file, 'a.rt');
  assert.equal(out.diagnostics[0].line, 1);
});

test('bad arguments throw an Error and the compiler goes on working', () => {
  assert.throws(() => compiler.compile(42, 'a.rt'), /files/);
  assert.throws(() => compiler.compile({ 'a.rt': 7 }, 'a.rt'), /string or a Uint8Array/);
  assert.throws(() => compiler.compile({}, 'a.rt', { exec: 'sideways' }), /exec/);
  assert.equal(compiler.check({ 'ok.rt': 'fn f() -> f32 { return 1.0; }\n' }).ok, true);
});

console.log(`${passed} tests passed`);
