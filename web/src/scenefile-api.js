// window.scenefile: check, convert and render for programs and tests,
// giving what sfcheck --format json, sfconvert and sfrender's 8-bit image
// give. render() has a worker of its own, independent of the page's
// progressive render, and runs one render at a time.
import { RenderClient } from './render-client.js';

export function createScenefileApi(library, wasmModule, version) {
  let client = null;
  let queue = Promise.resolve();

  function renderOnce(text, options) {
    client ??= new RenderClient(wasmModule);
    return new Promise((resolve, reject) => {
      let image = null;
      let threads = 1;
      client.render(text, '<stdin>', options ?? {}, false, {
        status({ status }) {
          if (!status.ok) return;
          image = new Uint8ClampedArray(status.width * status.height * 4);
          image.width = status.width;
          image.height = status.height;
          threads = status.threads;
        },
        band({ width, y0, pixels }) {
          image.set(pixels, y0 * width * 4);
        },
        done() {
          image.threads = threads;
          resolve(image);
        },
        error({ message, diagnostics }) {
          // As convert(): a scene's first error's own message; an option
          // refused, sfrender's message.
          const first = diagnostics?.find((d) => d.severity === 'error');
          const error = new Error(first ? first.message : message);
          error.diagnostics = diagnostics ?? [];
          reject(error);
        },
      });
    });
  }

  return {
    version,
    threads: self.crossOriginIsolated ? navigator.hardwareConcurrency : 1,
    check(text, name = '<stdin>') {
      const { format, diagnostics } = library.check(text, name);
      diagnostics.format = format;
      return diagnostics;
    },
    convert(text, to) {
      return library.convert(text, '<stdin>', to);
    },
    render(text, options = {}) {
      const result = queue.then(() => renderOnce(text, options));
      queue = result.catch(() => {});
      return result;
    },
  };
}
