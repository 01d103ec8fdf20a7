// Passes glTF files through glTF-Transform's operations that keep geometry
// (copy, dedup, prune, weld, resample, instance, reorder), each with its
// defaults, as `gltf-transform OPERATION IN OUT` would.
// Usage: node transform.mjs OUTDIR FILE... writes OUTDIR/OPERATION/FILE's name.
import { Logger, NodeIO } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { dedup, instance, prune, reorder, resample, weld } from '@gltf-transform/functions';
import { MeshoptEncoder } from 'meshoptimizer';
import { mkdirSync } from 'node:fs';
import { basename, join } from 'node:path';

const [outdir, ...files] = process.argv.slice(2);
await MeshoptEncoder.ready;
const operations = {
  copy: [],
  dedup: [dedup()],
  prune: [prune()],
  weld: [weld()],
  resample: [resample()],
  instance: [instance()],
  reorder: [reorder({ encoder: MeshoptEncoder })],
};
const logger = new Logger(Logger.Verbosity.WARN);
const io = new NodeIO().setLogger(logger).registerExtensions(ALL_EXTENSIONS);
for (const file of files) {
  for (const [name, transforms] of Object.entries(operations)) {
    const document = (await io.read(file)).setLogger(logger);
    await document.transform(...transforms);
    mkdirSync(join(outdir, name), { recursive: true });
    await io.write(join(outdir, name, basename(file)), document);
  }
}
