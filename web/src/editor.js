// The editor: CodeMirror 6 with the scene highlighter, diagnostics as you
// type, and the language server's hover and completion, all answered by
// the main thread's module synchronously.
import { EditorState } from '@codemirror/state';
import {
  EditorView, keymap, lineNumbers, highlightActiveLine, highlightActiveLineGutter,
  drawSelection, hoverTooltip,
} from '@codemirror/view';
import { defaultKeymap, history, historyKeymap, indentWithTab } from '@codemirror/commands';
import { syntaxHighlighting, defaultHighlightStyle } from '@codemirror/language';
import { linter, lintGutter, lintKeymap, forceLinting } from '@codemirror/lint';
import { autocompletion, completionKeymap, snippet } from '@codemirror/autocomplete';
import { searchKeymap, highlightSelectionMatches } from '@codemirror/search';
import { sceneLanguage, sceneHighlightStyle } from './scene-language.js';
import { toEditorDiagnostics } from './diagnostics.js';
import { lspPosition, fromLspPosition } from './positions.js';
import { markupToDom } from './markdown.js';

export { forceLinting };

const LINT_DELAY_MS = 150;

function hoverExtension(features) {
  return hoverTooltip((view, pos) => {
    const { line, character } = lspPosition(view.state.doc, pos);
    const answer = JSON.parse(features.hover(view.state.doc.toString(), line, character));
    if (!answer || !answer.contents) return null;
    const range = answer.range;
    return {
      pos: range ? fromLspPosition(view.state.doc, range.start) : pos,
      end: range ? fromLspPosition(view.state.doc, range.end) : pos,
      above: true,
      create: () => ({ dom: markupToDom(answer.contents) }),
    };
  });
}

// LSP snippet syntax to CodeMirror's: `$0`/`$1` become `${0}`/`${1}`, and a
// choice `${1|A,B|}` becomes its first choice as the field's text.
function toCodeMirrorSnippet(text) {
  return text
    .replace(/\$\{(\d+)\|([^,|}]*)[^}]*\|\}/g, '${$1:$2}')
    .replace(/\$(\d+)/g, '${$1}');
}

function completionOption(item, doc) {
  const edit = item.textEdit;
  const newText = edit ? edit.newText : (item.insertText ?? item.label);
  const option = {
    label: item.label,
    detail: item.detail,
    type: item.kind === 15 ? 'text' : 'keyword',
    boost: item.sortText?.startsWith('0') ? 1 : 0,
  };
  if (item.documentation) option.info = () => markupToDom(item.documentation);
  const from = edit ? fromLspPosition(doc, edit.range.start) : null;
  const to = edit ? fromLspPosition(doc, edit.range.end) : null;
  const apply = item.insertTextFormat === 2 ? snippet(toCodeMirrorSnippet(newText)) : null;
  option.apply = (view, completion, defaultFrom, defaultTo) => {
    const start = from ?? defaultFrom;
    const end = Math.max(to ?? defaultTo, defaultTo);
    if (apply) apply(view, completion, start, end);
    else view.dispatch({ changes: { from: start, to: end, insert: newText }, selection: { anchor: start + newText.length } });
  };
  return option;
}

function completionSource(features) {
  return (context) => {
    const doc = context.state.doc;
    const { line, character } = lspPosition(doc, context.pos);
    const answer = JSON.parse(features.completion(doc.toString(), line, character));
    const items = Array.isArray(answer) ? answer : answer?.items;
    if (!items || items.length === 0) return null;
    const word = context.matchBefore(/[A-Za-z_]*/);
    if (!context.explicit && word.from === word.to) return null;
    return { from: word.from, options: items.map((item) => completionOption(item, doc)), validFor: /^[A-Za-z_]*$/ };
  };
}

// features: {check(state) -> library diagnostics, hover, completion};
// onChange(update) is called after each edit.
export function createEditor(parent, text, features, onChange) {
  const lint = linter((view) => toEditorDiagnostics(features.check(view.state), view.state.doc), {
    delay: LINT_DELAY_MS,
  });
  const state = EditorState.create({
    doc: text,
    extensions: [
      // Only \n ends a line: a file's \r\n or lone \r stays in the text, so
      // that the check sees the file as it is.
      EditorState.lineSeparator.of('\n'),
      lineNumbers(), highlightActiveLineGutter(), highlightActiveLine(), history(), drawSelection(),
      highlightSelectionMatches(), sceneLanguage, syntaxHighlighting(sceneHighlightStyle), syntaxHighlighting(defaultHighlightStyle, { fallback: true }),
      lint, lintGutter(), hoverExtension(features),
      autocompletion({ override: [completionSource(features)], icons: false }),
      keymap.of([...completionKeymap, ...lintKeymap, ...searchKeymap, ...historyKeymap, ...defaultKeymap, indentWithTab]),
      EditorView.updateListener.of((update) => { if (update.docChanged) onChange(update); }),
    ],
  });
  return new EditorView({ state, parent });
}

// Replaces the whole text (a file opened, an example chosen).
export function replaceText(view, text) {
  view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text }, selection: { anchor: 0 } });
  view.scrollDOM.scrollTop = 0;
}

// Puts the cursor on a 1-based line and column range and shows it.
export function goTo(view, range) {
  view.dispatch({ selection: { anchor: range.from, head: range.to }, scrollIntoView: true });
  view.focus();
}
