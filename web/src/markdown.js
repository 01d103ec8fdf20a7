// The language server's answers are Markdown (bold, code spans, fenced code
// blocks, paragraphs); this builds them as DOM nodes, never as HTML text,
// so that nothing a scene holds can become markup.

function appendInline(parent, text) {
  const pattern = /\*\*([^*]+)\*\*|`([^`]+)`/g;
  let last = 0;
  for (const match of text.matchAll(pattern)) {
    parent.append(text.slice(last, match.index));
    const node = document.createElement(match[1] !== undefined ? 'strong' : 'code');
    node.textContent = match[1] ?? match[2];
    parent.append(node);
    last = match.index + match[0].length;
  }
  parent.append(text.slice(last));
}

export function markdownToDom(markdown) {
  const root = document.createElement('div');
  root.className = 'markdown';
  const blocks = markdown.split(/(```[^\n]*\n[\s\S]*?```)/);
  for (const block of blocks) {
    if (block.startsWith('```')) {
      const pre = document.createElement('pre');
      pre.textContent = block.replace(/^```[^\n]*\n/, '').replace(/```$/, '');
      root.append(pre);
      continue;
    }
    for (const paragraph of block.split(/\n{2,}/)) {
      if (!paragraph.trim()) continue;
      const p = document.createElement('p');
      appendInline(p, paragraph.trim());
      root.append(p);
    }
  }
  return root;
}

// LSP MarkupContent, a MarkedString or a plain string, as DOM.
export function markupToDom(contents) {
  if (typeof contents === 'string') return markdownToDom(contents);
  if (Array.isArray(contents)) {
    const root = document.createElement('div');
    for (const item of contents) root.append(markupToDom(item));
    return root;
  }
  if (contents && contents.kind === 'plaintext') {
    const p = document.createElement('p');
    p.textContent = contents.value;
    return p;
  }
  return markdownToDom(contents?.value ?? '');
}
