// The problems list: every diagnostic with its severity, line:column,
// message and code; a click goes to its span in the editor.

export function showProblems(list, diagnostics, onSelect) {
  list.replaceChildren();
  for (const d of diagnostics) {
    const item = document.createElement('li');
    item.className = `problem ${d.severity}`;
    item.dataset.line = String(d.line ?? 0);
    item.dataset.column = String(d.column ?? 0);
    item.dataset.code = d.code;
    item.tabIndex = 0;
    const severity = document.createElement('span');
    severity.className = 'severity';
    severity.textContent = d.severity;
    const where = document.createElement('span');
    where.className = 'where';
    where.textContent = d.line ? `${d.line}:${d.column}` : '';
    const message = document.createElement('span');
    message.className = 'message';
    message.textContent = d.message;
    const code = document.createElement('span');
    code.className = 'code';
    code.textContent = d.code;
    item.append(severity, where, message, code);
    if (d.hint) {
      const hint = document.createElement('div');
      hint.className = 'hint';
      hint.textContent = d.hint;
      item.append(hint);
    }
    item.addEventListener('click', () => onSelect(d));
    item.addEventListener('keydown', (event) => { if (event.key === 'Enter') onSelect(d); });
    list.append(item);
  }
  list.dataset.count = String(diagnostics.length);
}
