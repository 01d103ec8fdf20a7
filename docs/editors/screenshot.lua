-- Neovim's side of make_screenshot.sh: sfls on the file being edited, its
-- diagnostic shown, then the hover of a CUBE's matrix number open; then it
-- writes the file named by $READY, for the picture to be taken.
local function fail(message)
  io.stderr:write('make_screenshot: ' .. message .. '\n')
  vim.cmd('cquit 1')
end

require('scenefile').setup({ cmd = { os.getenv('SFLS') } })
local bufnr = vim.api.nvim_get_current_buf()
if not vim.wait(10000, function() return #vim.diagnostic.get(bufnr) > 0 end, 50) then
  fail('no diagnostic within 10 s')
  return
end
-- The CUBE's second matrix row, its fourth number: the translation along y.
local cube = vim.fn.search('^CUBE$', 'n')
vim.api.nvim_win_set_cursor(0, { cube + 3, #'0 0.5 0 ' })
vim.lsp.buf.hover()
local function hover_open()
  for _, window in ipairs(vim.api.nvim_list_wins()) do
    if vim.api.nvim_win_get_config(window).relative ~= '' then
      return true
    end
  end
  return false
end
if not vim.wait(10000, hover_open, 50) then
  fail('no hover within 10 s')
  return
end
vim.cmd('redraw!')
vim.defer_fn(function()
  vim.fn.writefile({}, os.getenv('READY'))
end, 300)
