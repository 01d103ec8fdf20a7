// The library's diagnostics (sfcheck --format json's objects) as
// CodeMirror lint diagnostics: the span underlined, the hint shown with the
// message, the fix-it as a one-click action.
import { spanToRange } from './positions.js';

const SEVERITIES = { error: 'error', warning: 'warning', note: 'info' };

function describeFix(fixIt, doc) {
  const range = spanToRange(doc, fixIt.line, fixIt.column, fixIt.length);
  if (!range) return null;
  const removed = doc.sliceString(range.from, range.to);
  let label;
  if (!fixIt.replacement) label = `Fix: remove "${removed}"`;
  else if (!removed) label = `Fix: insert "${fixIt.replacement}"`;
  else label = `Fix: "${removed}" → "${fixIt.replacement}"`;
  return {
    name: label,
    apply(view) {
      // The text may have changed since the check: the span is found again.
      const now = spanToRange(view.state.doc, fixIt.line, fixIt.column, fixIt.length);
      if (!now) return;
      view.dispatch({ changes: { from: now.from, to: now.to, insert: fixIt.replacement } });
    },
  };
}

function messageNode(d) {
  const node = document.createElement('div');
  node.className = 'lint-message';
  const message = document.createElement('div');
  message.textContent = `${d.message} [${d.code}]`;
  node.append(message);
  if (d.hint) {
    const hint = document.createElement('div');
    hint.className = 'lint-hint';
    hint.textContent = d.hint;
    node.append(hint);
  }
  for (const note of d.notes ?? []) {
    const line = document.createElement('div');
    line.className = 'lint-note';
    line.textContent = note.line ? `${note.line}:${note.column}: ${note.message}` : note.message;
    node.append(line);
  }
  return node;
}

// One CodeMirror diagnostic per library diagnostic; one whose span is
// unknown marks the first line, one of zero length marks its whole line.
export function toEditorDiagnostics(diagnostics, doc) {
  return diagnostics.map((d) => {
    let range = spanToRange(doc, d.line, d.column, d.length);
    if (!range) range = spanToRange(doc, 1, 0, 0);
    let { from, to } = range;
    if (from === to) {
      const line = doc.lineAt(from);
      from = line.from;
      to = line.to;
    }
    const fix = d.fixIt ? describeFix(d.fixIt, doc) : null;
    return {
      from,
      to,
      severity: SEVERITIES[d.severity] ?? 'info',
      message: d.message + (d.hint ? `\n${d.hint}` : ''),
      source: d.code,
      renderMessage: () => messageNode(d),
      actions: fix ? [fix] : [],
    };
  });
}
