-- sfls in a real client: Neovim 0.7's, set up by editors/nvim. For an
-- instruction file and a scene file with a typo each (tests/sfls/neovim/):
-- the diagnostic sfcheck gives, at its line and column; its quick fix applied,
-- after which the file written is byte for byte what `sfcheck --fix` writes;
-- formatting that keeps every word and is done after one pass; hover,
-- completion and document symbols.
--
--   SFLS=build/bin/sfls SFCHECK=build/bin/sfcheck \
--   nvim --headless --clean --cmd 'set rtp+=editors/nvim' -c 'luafile tests/sfls/neovim_test.lua'
--
-- Exits 0 when every check holds, else 1 with the first failure on standard
-- error. Every wait has a time limit, so that it never hangs.
local here = vim.fn.fnamemodify(debug.getinfo(1, 'S').source:sub(2), ':p:h')
local timeout_ms = 10000
local sfcheck -- set by main, from the environment

local function fail(message, ...)
  error(string.format(message, ...), 0)
end

local function check(condition, message, ...)
  if not condition then
    fail(message, ...)
  end
end

local function read_file(path)
  local file = assert(io.open(path, 'rb'))
  local bytes = file:read('*a')
  file:close()
  return bytes
end

local function copy(from, to)
  local file = assert(io.open(to, 'wb'))
  file:write(read_file(from))
  file:close()
end

local function wait_for(what, condition)
  if not vim.wait(timeout_ms, condition, 20) then
    fail('waited %d ms for %s', timeout_ms, what)
  end
end

local function client_of(bufnr)
  local clients = vim.lsp.buf_get_clients(bufnr)
  local _, client = next(clients)
  return client
end

-- The one client's answer to a request about the buffer.
local function request(bufnr, method, params)
  local answers, err = vim.lsp.buf_request_sync(bufnr, method, params, timeout_ms)
  check(answers, '%s: %s', method, tostring(err))
  local _, answer = next(answers)
  check(answer, '%s: no answer', method)
  check(not answer.error, '%s: error %s', method, vim.inspect(answer.error))
  return answer.result
end

local function document(bufnr)
  return { uri = vim.uri_from_bufnr(bufnr) }
end

local function buffer_text(bufnr)
  return table.concat(vim.api.nvim_buf_get_lines(bufnr, 0, -1, false), '\n') .. '\n'
end

local function words(text)
  return vim.split(vim.trim(text), '%s+')
end

local function hover_text(bufnr, line, character)
  local result = request(bufnr, 'textDocument/hover', {
    textDocument = document(bufnr),
    position = { line = line, character = character },
  })
  check(result and result.contents, 'hover at %d:%d: nothing', line, character)
  return table.concat(vim.lsp.util.convert_input_to_markdown_lines(result.contents), '\n')
end

-- The 0-based line of the first line that is `text` once trimmed.
local function line_of(bufnr, text)
  for index, line in ipairs(vim.api.nvim_buf_get_lines(bufnr, 0, -1, false)) do
    if vim.trim(line) == text then
      return index - 1
    end
  end
  fail('no line %q', text)
end

-- The file's diagnostic as sfcheck reports it, and as Neovim received it.
local function check_diagnostic(bufnr, path, case)
  wait_for('the diagnostic of ' .. case.file, function()
    return #vim.diagnostic.get(bufnr) > 0
  end)
  local received = vim.diagnostic.get(bufnr)
  check(#received == 1, '%s: %d diagnostics, expected 1', case.file, #received)
  local diagnostic = received[1]
  local report = vim.fn.json_decode(vim.fn.system({ sfcheck, '--format', 'json', path }))
  local expected = report.files[1].diagnostics[1]
  check(diagnostic.lnum == case.line and diagnostic.col == case.column,
        '%s: diagnostic at %d:%d, expected %d:%d (0-based)', case.file, diagnostic.lnum,
        diagnostic.col, case.line, case.column)
  check(expected.line - 1 == case.line and expected.column - 1 == case.column,
        '%s: sfcheck reports %d:%d', case.file, expected.line, expected.column)
  check(diagnostic.code == expected.code, '%s: code %s, expected %s', case.file,
        tostring(diagnostic.code), expected.code)
  check(diagnostic.message:find(expected.message, 1, true) == 1, '%s: message %q, expected %q',
        case.file, diagnostic.message, expected.message)
  check(diagnostic.severity == vim.diagnostic.severity.ERROR, '%s: not an error', case.file)
  -- In the protocol's form again, as vim.lsp.buf.code_action sends it.
  return vim.lsp.diagnostic.get_line_diagnostics(bufnr, case.line)[1]
end

local function apply_quick_fix(bufnr, diagnostic)
  local actions = request(bufnr, 'textDocument/codeAction', {
    textDocument = document(bufnr),
    range = diagnostic.range,
    context = { diagnostics = { diagnostic } },
  })
  check(actions and #actions == 1, 'code actions: %s, expected one', vim.inspect(actions))
  local action = actions[1]
  check(action.kind == 'quickfix' and action.edit, 'not a quick fix with an edit: %s',
        vim.inspect(action))
  check(action.isPreferred == true, 'the only quick fix is not marked preferred')
  vim.lsp.util.apply_workspace_edit(action.edit, client_of(bufnr).offset_encoding)
  wait_for('the diagnostics to clear after the fix', function()
    return #vim.diagnostic.get(bufnr) == 0
  end)
end

-- The file written after the fix against what `sfcheck --fix` writes of the
-- original: byte for byte.
local function check_same_as_sfcheck_fix(case, path, work)
  vim.cmd('silent write')
  local fixed = work .. '/by-sfcheck-' .. case.file
  copy(here .. '/neovim/' .. case.file, fixed)
  local output = vim.fn.system({ sfcheck, '--fix', fixed })
  check(vim.v.shell_error == 0, 'sfcheck --fix %s failed: %s', fixed, output)
  local ours, theirs = read_file(path), read_file(fixed)
  check(ours == theirs, '%s after the code action differs from sfcheck --fix:\n%s\n--- against ---\n%s',
        case.file, ours, theirs)
end

local function check_formatting(bufnr)
  local before = buffer_text(bufnr)
  local params = { textDocument = document(bufnr), options = { tabSize = 2, insertSpaces = true } }
  local edits = request(bufnr, 'textDocument/formatting', params)
  check(edits and #edits > 0, 'formatting a file out of layout gave no edits')
  vim.lsp.util.apply_text_edits(edits, bufnr, client_of(bufnr).offset_encoding)
  local after = buffer_text(bufnr)
  check(vim.deep_equal(words(before), words(after)), 'formatting changed a word:\n%s', after)
  local again = request(bufnr, 'textDocument/formatting', params)
  check(again == nil or #again == 0, 'formatting twice changed more: %s', vim.inspect(again))
end

local function completion_labels(bufnr, line, character)
  local result = request(bufnr, 'textDocument/completion', {
    textDocument = document(bufnr),
    position = { line = line, character = character },
  })
  local labels = {}
  for _, item in ipairs(result and (result.items or result) or {}) do
    labels[item.label] = true
  end
  return labels
end

-- Each symbol names what `expected` gives in that place, and has the
-- children `children` gives it (none where it gives none).
local function check_symbol_names(symbols, expected, children, where)
  check(symbols and #symbols == #expected, '%s: %s, expected %d', where, vim.inspect(symbols), #expected)
  for index, word in ipairs(expected) do
    local symbol = symbols[index]
    check(symbol.name:find(word, 1, true), '%s %d is %q, expected it to name %s', where, index,
          symbol.name, word)
    check_symbol_names(symbol.children or {}, children[index] or {}, {}, symbol.name .. "'s child")
  end
end

local function check_symbols(bufnr, case)
  local symbols = request(bufnr, 'textDocument/documentSymbol', { textDocument = document(bufnr) })
  check_symbol_names(symbols, case.symbols, case.children or {}, 'symbol')
end

local cases = {
  {
    file = 'typo.txt',
    filetype = 'scenefile_instructions',
    line = 13,
    column = 4,
    symbols = { 'OUTPUT_FILE', 'CAMERA', 'LIGHT', 'SPHERE', 'CUBE' },
    -- The objects' sections, nested in them.
    children = { [4] = { 'MATERIAL', 'TRANSFORMATION' }, [5] = { 'TRANSFORMATION' } },
    features = function(bufnr)
      -- A MATERIAL key's meaning and the values it takes.
      local ambient = line_of(bufnr, 'AMBIENT 0.05')
      local text = hover_text(bufnr, ambient, 5)
      check(text:find('AMBIENT', 1, true) and text:find('0 to 1', 1, true),
            'hover on AMBIENT: %q', text)
      -- The MATERIAL keys not given yet, on a new line of the block.
      vim.api.nvim_buf_set_lines(bufnr, ambient + 1, ambient + 1, false, { '    ' })
      local labels = completion_labels(bufnr, ambient + 1, 4)
      vim.api.nvim_buf_set_lines(bufnr, ambient + 1, ambient + 2, false, {})
      for _, key in ipairs({ 'DIFFUSE', 'SPECULAR', 'SHININESS', 'REFLECTIVITY', 'TRANSPARENCY', 'RI' }) do
        check(labels[key], 'completion in MATERIAL lacks %s: %s', key, vim.inspect(labels))
      end
      for _, key in ipairs({ 'COLOUR', 'AMBIENT', 'LOCATION', 'SCALE' }) do
        check(not labels[key], 'completion in MATERIAL offers %s: %s', key, vim.inspect(labels))
      end
    end,
  },
  {
    file = 'typo.sf',
    filetype = 'scenefile',
    line = 19,
    column = 0,
    symbols = { 'CAMERA', 'LIGHT', 'PLANE', 'SPHERE' },
    features = function(bufnr)
      -- The fourth number of the matrix's second row: the translation along y.
      local row2 = line_of(bufnr, 'SPHERE') + 3
      local text = hover_text(bufnr, row2, #'0 1 0 ')
      check(text:find('row 2, column 4', 1, true) and text:find('translation along y', 1, true),
            'hover on a matrix number: %q', text)
      -- Record names where a record starts: on a new line at the end.
      local last = vim.api.nvim_buf_line_count(bufnr)
      vim.api.nvim_buf_set_lines(bufnr, last, last, false, { '', '' })
      local labels = completion_labels(bufnr, last + 1, 0)
      vim.api.nvim_buf_set_lines(bufnr, last, last + 2, false, {})
      check(labels.SPHERE and labels.CUBE and labels.LIGHT, 'completion where a record starts: %s',
            vim.inspect(labels))
    end,
  },
}

local function run(case, work)
  local path = work .. '/' .. case.file
  vim.cmd('edit ' .. vim.fn.fnameescape(path))
  local bufnr = vim.api.nvim_get_current_buf()
  check(vim.bo[bufnr].filetype == case.filetype, '%s: filetype %q, expected %q', case.file,
        vim.bo[bufnr].filetype, case.filetype)
  wait_for('sfls attached to ' .. case.file, function()
    return client_of(bufnr) ~= nil and client_of(bufnr).initialized
  end)
  apply_quick_fix(bufnr, check_diagnostic(bufnr, path, case))
  check_same_as_sfcheck_fix(case, path, work)
  check_formatting(bufnr)
  case.features(bufnr)
  check_symbols(bufnr, case)
  check(#vim.diagnostic.get(bufnr) == 0, '%s: diagnostics after formatting', case.file)
end

local function program(variable)
  local path = os.getenv(variable)
  check(path and vim.fn.executable(path) == 1, '%s is not set to a program: %s', variable, tostring(path))
  return vim.fn.fnamemodify(path, ':p')
end

-- Everything runs inside pcall: an error outside it would leave a headless
-- Neovim waiting for input.
local ok, err = pcall(function()
  sfcheck = program('SFCHECK')
  require('scenefile').setup({ cmd = { program('SFLS') } })
  local work = vim.fn.tempname()
  vim.fn.mkdir(work, 'p')
  -- Both files opened at once, under one root folder: one server for both,
  -- even while it is starting.
  vim.o.hidden = true
  for _, case in ipairs(cases) do
    copy(here .. '/neovim/' .. case.file, work .. '/' .. case.file)
    vim.cmd('edit ' .. vim.fn.fnameescape(work .. '/' .. case.file))
  end
  wait_for('sfls to start', function()
    return #vim.lsp.get_active_clients() > 0
  end)
  vim.wait(200) -- time for a second server to start, were one started
  check(#vim.lsp.get_active_clients() == 1, '%d servers for one folder', #vim.lsp.get_active_clients())
  for _, case in ipairs(cases) do
    run(case, work)
    io.stderr:write('neovim: ' .. case.file .. ': every check holds\n')
  end
end)
if not ok then
  io.stderr:write('neovim: ' .. tostring(err) .. '\n')
  vim.cmd('cquit 1')
end
vim.cmd('qall!')
