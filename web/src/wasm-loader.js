// Loads the main thread's module: its wasm compiled while it downloads, and
// the same compiled module handed to the render worker when the page is
// not cross-origin isolated (one compile for both).

export function compileWasm(url) {
  return WebAssembly.compileStreaming(fetch(url)).catch(async () => {
    // A server that sends .wasm without its MIME type still works.
    const bytes = await (await fetch(url)).arrayBuffer();
    return WebAssembly.compile(bytes);
  });
}

export async function instantiateModule(factory, wasmModule) {
  const compiled = await wasmModule;
  return factory({
    instantiateWasm(imports, receive) {
      WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled));
      return {};
    },
  });
}
