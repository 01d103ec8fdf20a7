// The library counts columns in bytes of the UTF-8 line, 1-based, and the
// first line's after a byte-order mark; CodeMirror counts UTF-16 units from
// the document's start. These convert between the two.

const BOM = '\uFEFF';

function utf8Length(codePoint) {
  if (codePoint < 0x80) return 1;
  if (codePoint < 0x800) return 2;
  if (codePoint < 0x10000) return 3;
  return 4;
}

// The UTF-16 index in `text` where byte `byteIndex` (0-based) of its UTF-8
// encoding starts; a byte inside a character gives that character's end,
// and one past the end gives the text's length.
function utf16IndexOfByte(text, byteIndex) {
  let bytes = 0;
  let i = 0;
  while (i < text.length && bytes < byteIndex) {
    const codePoint = text.codePointAt(i);
    bytes += utf8Length(codePoint);
    i += codePoint > 0xffff ? 2 : 1;
  }
  return i;
}

// The first UTF-16 index of `line` that the library counts columns from.
function columnOrigin(line) {
  return line.number === 1 && line.text.startsWith(BOM) ? 1 : 0;
}

// The document range {from, to} of a span (1-based line and byte column,
// length in bytes), or null where the span is unknown or off the document.
export function spanToRange(doc, lineNumber, column, length) {
  if (!lineNumber || lineNumber > doc.lines) return null;
  const line = doc.line(lineNumber);
  if (!column) return { from: line.from, to: line.from, wholeLine: true };
  const text = line.text.slice(columnOrigin(line));
  const origin = line.from + columnOrigin(line);
  const start = utf16IndexOfByte(text, column - 1);
  const end = utf16IndexOfByte(text, column - 1 + (length || 0));
  return { from: origin + start, to: origin + end, wholeLine: false };
}

// The 0-based line and UTF-16 character of a document position, as the
// language server's hover and completion take them.
export function lspPosition(doc, pos) {
  const line = doc.lineAt(pos);
  return { line: line.number - 1, character: pos - line.from };
}

// The document position of an LSP position (0-based line, UTF-16 units).
export function fromLspPosition(doc, position) {
  const lineNumber = Math.min(position.line + 1, doc.lines);
  const line = doc.line(lineNumber);
  return Math.min(line.from + position.character, line.to);
}
