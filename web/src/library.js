// The main thread's module (scenefile.js, no threads) with its answers
// parsed: what the editor, the downloads and window.scenefile call.

export class Library {
  constructor(module) {
    this.module = module;
    this.formats = JSON.parse(module.formats());
  }

  // {format, diagnostics}: sfcheck --format json's diagnostics for `input`
  // (a string, or a Uint8Array of the file's bytes).
  check(input, name) {
    return JSON.parse(this.module.check(input, name));
  }

  // {output (a string, a Uint8Array for glb, or null), materialLibrary (an
  // .obj's MTL file where `materialLibrary` names it, else ''), diagnostics
  // (an array)}.
  convertRaw(input, name, to, materialLibrary = '') {
    const result = this.module.convert(input, name, to, materialLibrary);
    let output = result.output ?? null;
    // Bytes as a Uint8Array whatever typed array the module answers, and
    // copied: a view of the module's memory would change under the next call.
    if (ArrayBuffer.isView(output)) output = new Uint8Array(output.buffer, output.byteOffset, output.byteLength).slice();
    return { output, materialLibrary: result.materialLibrary, diagnostics: JSON.parse(result.diagnostics || '[]') };
  }

  // The output, or an Error whose message is the first error's and whose
  // `diagnostics` holds them all.
  convert(input, name, to) {
    return this.convertFiles(input, name, to, '').output;
  }

  // As convert, with an .obj's MTL file named `materialLibrary`, as
  // sfconvert writes NAME.obj and NAME.mtl: {output, materialLibrary}.
  convertFiles(input, name, to, materialLibrary) {
    const result = this.convertRaw(input, name, to, materialLibrary);
    const { output, diagnostics } = result;
    if (output !== null) return result;
    const first = diagnostics.find((d) => d.severity === 'error') ?? diagnostics[0];
    const error = new Error(first ? first.message : `cannot convert to ${to}`);
    error.diagnostics = diagnostics;
    throw error;
  }

  hover(text, line, character) {
    return this.module.hover(text, line, character);
  }

  completion(text, line, character) {
    return this.module.completion(text, line, character);
  }

  defaultScene() {
    return { name: this.module.defaultSceneName(), text: this.module.defaultScene() };
  }
}
