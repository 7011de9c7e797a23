-- The Povrayst language server for Neovim's built-in client (0.7 and later), and for
-- nvim-lspconfig. `require('povrayst').setup()` starts `povrayst lsp` for POV-Ray buffers
-- (filetype `pov`) and Typst buffers (served inside their povray blocks), one server per
-- project root.
local M = {}

M.defaults = {
  -- The command line of the server.
  cmd = { 'povrayst', 'lsp' },
  filetypes = { 'pov', 'typst' },
  -- Directories searched for includes after the scene's own (POV-Ray's +L).
  library_paths = {},
  -- Evaluation budgets, so that a runaway scene cannot hang the editor.
  budgets = { loopIterations = 10000000, macroDepth = 1000, steps = 200000000 },
  -- Files or directories that mark a project root.
  root_markers = { '.git' },
}

M.options = vim.deepcopy(M.defaults)

--- What the server is told in `initialize` (the same as the VS Code extension sends).
function M.init_options(options)
  return { libraryPaths = options.library_paths, budgets = options.budgets }
end

--- The nearest directory above `path` holding a root marker, or the file's own directory.
function M.root_dir(path, markers)
  local dir = vim.fn.fnamemodify(path, ':p:h')
  for _, marker in ipairs(markers) do
    local found = vim.fn.finddir(marker, dir .. ';')
    if found == '' then
      found = vim.fn.findfile(marker, dir .. ';')
    end
    if found ~= '' then
      return vim.fn.fnamemodify(found, ':p:h:h')
    end
  end
  return dir
end

-- Client ids by root directory, for Neovim 0.7, which has no vim.lsp.start to reuse them.
local clients = {}

local function config_for(bufnr, options)
  local root = M.root_dir(vim.api.nvim_buf_get_name(bufnr), options.root_markers)
  return {
    name = 'povrayst',
    cmd = options.cmd,
    root_dir = root,
    workspace_folders = { { uri = vim.uri_from_fname(root), name = root } },
    init_options = M.init_options(options),
    settings = { povrayst = M.init_options(options) },
    on_attach = options.on_attach,
    capabilities = options.capabilities,
  }
end

--- Starts the server for a buffer, or attaches the buffer to the one already running for
--- its project.
function M.attach(bufnr, options)
  options = options or M.options
  local config = config_for(bufnr, options)
  if vim.lsp.start then
    return vim.lsp.start(config, { bufnr = bufnr })
  end
  local id = clients[config.root_dir]
  if id == nil or vim.lsp.get_client_by_id(id) == nil then
    id = vim.lsp.start_client(config)
    clients[config.root_dir] = id
  end
  if id then
    vim.lsp.buf_attach_client(bufnr, id)
  end
  return id
end

--- Starts the server for every buffer of the configured filetypes, now and later.
function M.setup(options)
  M.options = vim.tbl_deep_extend('force', vim.deepcopy(M.defaults), options or {})
  local group = vim.api.nvim_create_augroup('povrayst', { clear = true })
  vim.api.nvim_create_autocmd('FileType', {
    group = group,
    pattern = M.options.filetypes,
    callback = function(event)
      M.attach(event.buf)
    end,
  })
  for _, bufnr in ipairs(vim.api.nvim_list_bufs()) do
    if vim.api.nvim_buf_is_loaded(bufnr) and vim.tbl_contains(M.options.filetypes, vim.bo[bufnr].filetype) then
      M.attach(bufnr)
    end
  end
end

--- Registers the server with nvim-lspconfig, for `require('lspconfig').povrayst.setup({})`.
function M.lspconfig(options)
  options = vim.tbl_deep_extend('force', vim.deepcopy(M.defaults), options or {})
  local configs = require('lspconfig.configs')
  if not configs.povrayst then
    configs.povrayst = {
      default_config = {
        cmd = options.cmd,
        filetypes = options.filetypes,
        root_dir = function(fname)
          return M.root_dir(fname, options.root_markers)
        end,
        init_options = M.init_options(options),
        settings = { povrayst = M.init_options(options) },
      },
    }
  end
  return configs.povrayst
end

--- `:PovrayRender [OPTION...]`: renders the current scene to a PNG beside it with
--- `povrayst render`, in the background; options are POV-Ray's (`+W640 +H480 +A0.3`).
function M.render(args)
  local scene = vim.api.nvim_buf_get_name(0)
  if scene == '' then
    vim.notify('PovrayRender: the buffer has no file', vim.log.levels.ERROR)
    return
  end
  if vim.bo.modified then
    vim.cmd('write')
  end
  local output = vim.fn.fnamemodify(scene, ':r') .. '.png'
  local command = { M.options.cmd[1], 'render', scene, '-o', output }
  for _, path in ipairs(M.options.library_paths) do
    vim.list_extend(command, { '-L', path })
  end
  vim.list_extend(command, args or {})
  local errors = {}
  return vim.fn.jobstart(command, {
    stderr_buffered = true,
    on_stderr = function(_, data)
      errors = data
    end,
    on_exit = function(_, status)
      if status == 0 then
        vim.notify('PovrayRender: wrote ' .. output)
      else
        vim.notify('PovrayRender failed:\n' .. table.concat(errors, '\n'), vim.log.levels.ERROR)
      end
    end,
  })
end

return M
