// Opening a file (drop or picker) and downloading the scene in each format
// the library writes, or the render as PNG.

function extensionOf(name) {
  const dot = name.lastIndexOf('.');
  return dot < 0 ? '' : name.slice(dot + 1).toLowerCase();
}

function withoutExtension(name) {
  const dot = name.lastIndexOf('.');
  return dot <= 0 ? name : name.slice(0, dot);
}

// The registry's row whose extensions hold `name`'s, or undefined.
export function formatOfName(formats, name) {
  const extension = extensionOf(name);
  return formats.find((f) => f.extensions.some((e) => e.replace(/^\./, '').toLowerCase() === extension));
}

export function fileNameFor(formats, documentName, to) {
  const format = formats.find((f) => f.name === to);
  const extension = (format?.extensions[0] ?? `.${to}`).replace(/^\.?/, '.');
  return withoutExtension(documentName) + extension;
}

// The MTL file beside an .obj, as sfconvert names it: NAME.obj -> NAME.mtl.
export function materialLibraryNameFor(objName) {
  return `${withoutExtension(objName)}.mtl`;
}

// What the editor gets for a file: {name, text, bytes, notice}. Text
// formats go in as they are; bytes are kept where the text is not UTF-8,
// so that the check sees the file itself until the text is edited. A
// binary format (.glb) is converted to a scene file for the editor; one
// that cannot be leaves the editor empty, with the file's diagnostics.
export async function readSceneFile(file, library) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  const format = formatOfName(library.formats, file.name);
  if (format?.binary) {
    const { output } = library.convertRaw(bytes, file.name, 'sf');
    if (output === null) {
      return { name: file.name, text: '', bytes, notice: `${file.name} cannot be converted to a scene file: see its problems.` };
    }
    const name = `${withoutExtension(file.name)}.sf`;
    return { name, text: output, bytes: null, notice: `${file.name} is binary: it was converted to ${name} for the editor.` };
  }
  try {
    const text = new TextDecoder('utf-8', { fatal: true, ignoreBOM: true }).decode(bytes);
    return { name: file.name, text, bytes: null, notice: '' };
  } catch {
    const text = new TextDecoder('utf-8', { ignoreBOM: true }).decode(bytes);
    return { name: file.name, text, bytes, notice: `${file.name} is not UTF-8: its problems are those of the file's own bytes until it is edited.` };
  }
}

export function saveBlob(blob, fileName) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

// Calls onFile(file) for a file dropped anywhere on the page.
export function acceptDrops(target, onFile) {
  target.addEventListener('dragover', (event) => {
    event.preventDefault();
    document.body.classList.add('dropping');
  });
  target.addEventListener('dragleave', (event) => {
    if (event.relatedTarget === null) document.body.classList.remove('dropping');
  });
  target.addEventListener('drop', (event) => {
    event.preventDefault();
    document.body.classList.remove('dropping');
    const file = event.dataTransfer?.files?.[0];
    if (file) onFile(file);
  });
}
