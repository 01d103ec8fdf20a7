// node web/build.mjs OUT_DIR: the page's static files into OUT_DIR, beside
// the modules that web/wasm/ built there: the scripts bundled and minified
// by esbuild (three.js in a chunk of its own, loaded after the first
// image), index.html, the style, coi-serviceworker's script, and the
// scenes of examples/ and docs/guide/ with an index for the page's menu.
import { build } from 'esbuild';
import { copyFileSync, mkdirSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const webDir = dirname(fileURLToPath(import.meta.url));
const root = resolve(webDir, '..');
if (process.argv.length !== 3) {
  console.error('usage: node web/build.mjs OUT_DIR');
  process.exit(2);
}
const out = resolve(process.argv[2]);
mkdirSync(out, { recursive: true });
// Chunks are named by their hash: the last build's would stay beside them.
rmSync(join(out, 'chunks'), { recursive: true, force: true });

// The project's version, from the root CMakeLists.txt's project().
const version = /project\(scenefile VERSION ([0-9.]+)/.exec(readFileSync(join(root, 'CMakeLists.txt'), 'utf8'))[1];

const common = {
  bundle: true,
  minify: true,
  sourcemap: false,
  target: 'es2022',
  logLevel: 'warning',
  absWorkingDir: webDir,
  define: { SCENEFILE_VERSION: JSON.stringify(version) },
};
await build({
  ...common,
  entryPoints: ['src/app.js'],
  outdir: out,
  format: 'esm',
  splitting: true,
  chunkNames: 'chunks/[name]-[hash]',
});
// Classic scripts: the worker loads the modules with importScripts, and
// boot.js runs before the page's bundle has loaded.
for (const name of ['render-worker.js', 'boot.js']) {
  await build({ ...common, entryPoints: [`src/${name}`], outfile: join(out, name), format: 'iife' });
}

for (const file of ['index.html', 'style.css']) copyFileSync(join(webDir, file), join(out, file));
const require = createRequire(import.meta.url);
copyFileSync(require.resolve('coi-serviceworker/coi-serviceworker.min.js'), join(out, 'coi-serviceworker.js'));

// The scenes the page's menu offers: every file of these folders in a
// format the library reads as text.
const SCENE_EXTENSIONS = /\.(sf|txt|gltf|pov)$/;
const groups = [
  { label: 'examples', source: join(root, 'examples'), folder: 'examples' },
  { label: 'docs/guide', source: join(root, 'docs/guide'), folder: 'guide' },
];
const index = { groups: [] };
for (const group of groups) {
  const files = readdirSync(group.source).filter((name) => SCENE_EXTENSIONS.test(name)).sort();
  mkdirSync(join(out, 'examples', group.folder), { recursive: true });
  for (const name of files) copyFileSync(join(group.source, name), join(out, 'examples', group.folder, name));
  index.groups.push({ label: group.label, files: files.map((name) => `${group.folder}/${name}`) });
}
writeFileSync(join(out, 'examples', 'index.json'), `${JSON.stringify(index, null, 2)}\n`);
