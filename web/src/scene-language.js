// Highlighting for both line formats: scene files (.sf: a record name, then
// lines of numbers) and instruction files (.txt: START/END blocks of keyword
// lines). One tokenizer serves both; the words are those of
// include/scenefile/keywords.h. Neither format has comments.
import { StreamLanguage, HighlightStyle } from '@codemirror/language';
import { tags } from '@lezer/highlight';

const BLOCK_WORDS = new Set(['START', 'END']);
const BLOCK_NAMES = new Set(['CAMERA', 'LIGHT', 'OBJECT', 'MATERIAL', 'TRANSFORMATION']);
const OBJECT_KINDS = new Set(['PLANE', 'CUBE', 'SPHERE', 'CYLINDER']);
const PROPERTIES = new Set([
  'OUTPUT_FILE', 'LOCATION', 'LOOK_AT', 'COLOUR', 'AMBIENT', 'DIFFUSE', 'SPECULAR',
  'SHININESS', 'REFLECTIVITY', 'TRANSPARENCY', 'RI',
]);
const OPERATIONS = new Set(['SCALE', 'TRANSLATE', 'ROTATE_X', 'ROTATE_Y', 'ROTATE_Z']);

const NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?(?=\s|$)/;

function wordStyle(word, state) {
  if (BLOCK_WORDS.has(word)) return 'keyword';
  if (BLOCK_NAMES.has(word)) return 'typeName';
  if (OBJECT_KINDS.has(word)) return state.firstWord ? 'typeName' : 'className';
  if (PROPERTIES.has(word)) return 'propertyName';
  if (OPERATIONS.has(word)) return 'macroName';
  // OUTPUT_FILE's argument is a file name, not a mistake.
  return state.afterOutputFile ? 'string' : 'invalid';
}

export const sceneLanguage = StreamLanguage.define({
  name: 'scenefile',
  startState: () => ({ firstWord: true, afterOutputFile: false }),
  token(stream, state) {
    if (stream.sol()) {
      state.firstWord = true;
      state.afterOutputFile = false;
    }
    if (stream.eatSpace()) return null;
    if (stream.match(NUMBER)) {
      state.firstWord = false;
      return 'number';
    }
    stream.match(/^\S+/);
    const word = stream.current();
    const style = wordStyle(word, state);
    state.afterOutputFile = word === 'OUTPUT_FILE';
    state.firstWord = false;
    return style;
  },
});

export const sceneHighlightStyle = HighlightStyle.define([
  { tag: tags.keyword, color: '#a626a4', fontWeight: 'bold' },
  { tag: tags.typeName, color: '#0e7c86' },
  { tag: tags.className, color: '#0e7c86', fontStyle: 'italic' },
  { tag: tags.propertyName, color: '#4078f2' },
  { tag: tags.macroName, color: '#c18401' },
  { tag: tags.number, color: '#50a14f' },
  { tag: tags.string, color: '#986801' },
  { tag: tags.invalid, color: '#e45649', textDecoration: 'underline dotted' },
]);
