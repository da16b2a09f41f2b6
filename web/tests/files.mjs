// web/tests/files.mjs: shared helpers of the Node tests: the repository's files as the in-memory
// file map the WebAssembly compiler takes (paths relative to the repository root, as `rtc`
// run there names them), and loading web/pkg/node.
import { createRequire } from 'node:module';
import { readdirSync, readFileSync, statSync, existsSync } from 'node:fs';
import { join, dirname, extname } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repo = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

/** The compiler (web/pkg/node, built by web/build.sh). */
export function loadCompiler() {
  const pkg = join(repo, 'web', 'pkg', 'node', 'rtc_web.js');
  if (!existsSync(pkg)) {
    throw new Error(`${pkg} is missing: run bash web/build.sh first`);
  }
  return createRequire(import.meta.url)(pkg);
}

const TEXT = new Set(['.rt', '.json']);
const BYTES = new Set(['.glb', '.gltf', '.bin']);

/** Every source, registry and model file under `dir` (relative to the repository), recursively:
 *  text as strings, glTF files as Uint8Arrays; images and everything else left out. */
export function filesUnder(dir, into = new Map()) {
  for (const name of readdirSync(join(repo, dir)).sort()) {
    const rel = `${dir}/${name}`;
    const full = join(repo, rel);
    if (statSync(full).isDirectory()) {
      filesUnder(rel, into);
    } else if (TEXT.has(extname(name))) {
      into.set(rel, readFileSync(full, 'utf8'));
    } else if (BYTES.has(extname(name))) {
      into.set(rel, new Uint8Array(readFileSync(full)));
    }
  }
  return into;
}

/** Every scene declared in the examples and the GPU test scenes: `{ file, scene }`, files relative
 *  to the repository, in path order. */
export function scenes() {
  const files = [];
  for (const name of readdirSync(join(repo, 'examples')).sort()) {
    if (existsSync(join(repo, 'examples', name, 'scene.rt'))) files.push(`examples/${name}/scene.rt`);
  }
  const walk = (dir) => {
    if (!existsSync(join(repo, dir))) return;
    for (const name of readdirSync(join(repo, dir)).sort()) {
      const rel = `${dir}/${name}`;
      if (statSync(join(repo, rel)).isDirectory()) walk(rel);
      else if (name.endsWith('.rt')) files.push(rel);
    }
  };
  walk('runtime/tests/scenes');
  walk('tests/scenes');
  const out = [];
  for (const file of files) {
    const text = readFileSync(join(repo, file), 'utf8');
    for (const m of text.matchAll(/^scene\s+([A-Za-z_][A-Za-z0-9_]*)/gm)) out.push({ file, scene: m[1] });
  }
  return out;
}
