-- sfls in Neovim's built-in client, with the API of Neovim 0.7 (Debian 12's):
-- vim.lsp.start_client and vim.lsp.buf_attach_client, no nvim-lspconfig.
--
--   require('scenefile').setup({ cmd = { 'sfls' } })
--
-- starts one sfls per root folder (the nearest folder above the file that
-- holds one of `root_markers`, else the file's own folder) when a buffer of
-- one of `filetypes` opens, and attaches every such buffer under that root
-- to it. It maps no keys: see editors/nvim/README.md.
local M = {}

local defaults = {
  cmd = { 'sfls' },
  filetypes = { 'scenefile', 'scenefile_instructions' },
  root_markers = { '.git' },
  -- Passed on to vim.lsp.start_client as they are.
  on_attach = nil,
  capabilities = nil,
  handlers = nil,
}

-- The client of each root folder, by the folder's absolute path.
local clients = {}

-- The folder a buffer's file belongs to, or nil for a buffer with no file.
local function root_of(bufnr, markers)
  local name = vim.api.nvim_buf_get_name(bufnr)
  if name == '' then
    return nil
  end
  local folder = vim.fn.fnamemodify(name, ':p:h')
  for _, marker in ipairs(markers) do
    -- A marker may be a folder (.git) or a file (.git of a worktree).
    local found = vim.fn.finddir(marker, folder .. ';')
    if found == '' then
      found = vim.fn.findfile(marker, folder .. ';')
    end
    if found ~= '' then
      local marker_path = vim.fn.fnamemodify(found, ':p'):gsub('/$', '')
      return vim.fn.fnamemodify(marker_path, ':h')
    end
  end
  return folder
end

local function client_for(root, config)
  local id = clients[root]
  -- Not vim.lsp.client_is_stopped: in 0.7 it calls a client that is still
  -- initializing stopped, and a second file opened meanwhile would start a
  -- second server.
  local running = id and vim.lsp.get_client_by_id(id)
  if running and not running.is_stopped() then
    return id
  end
  id = vim.lsp.start_client({
    name = 'sfls',
    cmd = config.cmd,
    root_dir = root,
    capabilities = config.capabilities,
    handlers = config.handlers,
    on_attach = config.on_attach,
    on_exit = function()
      clients[root] = nil
    end,
  })
  clients[root] = id
  return id
end

-- Attaches the buffer to the client of its root, starting that client if
-- there is none yet. Returns the client's id, or nil.
function M.attach(bufnr, config)
  config = config or M.config or defaults
  local root = root_of(bufnr, config.root_markers)
  if not root then
    return nil
  end
  local id = client_for(root, config)
  if id then
    vim.lsp.buf_attach_client(bufnr, id)
  end
  return id
end

function M.setup(options)
  M.config = vim.tbl_extend('force', defaults, options or {})
  local group = vim.api.nvim_create_augroup('scenefile_sfls', { clear = true })
  vim.api.nvim_create_autocmd('FileType', {
    group = group,
    pattern = M.config.filetypes,
    callback = function(event)
      M.attach(event.buf, M.config)
    end,
  })
  -- Buffers opened before setup ran.
  for _, bufnr in ipairs(vim.api.nvim_list_bufs()) do
    if vim.api.nvim_buf_is_loaded(bufnr) and vim.tbl_contains(M.config.filetypes, vim.bo[bufnr].filetype) then
      M.attach(bufnr, M.config)
    end
  end
end

return M
