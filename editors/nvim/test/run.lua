-- Neovim test of the plugin against the real server, run headless by test/run:
--   nvim --headless -u NONE -i NONE --cmd 'set rtp^=editors/nvim' -S test/run.lua
-- with $POVRAYST naming the povrayst binary and $GALLERY the gallery directory. It prints
-- one line per check and "N passed, N failed", and exits non-zero when a check failed.

local povrayst = require('povrayst')
local binary = assert(os.getenv('POVRAYST'), '$POVRAYST must name the povrayst binary')
local gallery = assert(os.getenv('GALLERY'), '$GALLERY must name the gallery directory')
local work = vim.fn.tempname()
vim.fn.mkdir(work, 'p')

local passed, failed = 0, 0

local function check(name, body)
  local ok, err = pcall(body)
  if ok then
    passed = passed + 1
    print('ok: ' .. name)
  else
    failed = failed + 1
    print('FAILED: ' .. name .. ': ' .. tostring(err))
  end
end

local function write(name, lines)
  local path = work .. '/' .. name
  vim.fn.writefile(lines, path)
  return path
end

local function wait_for(what, condition)
  assert(vim.wait(20000, condition, 50), 'timed out waiting for ' .. what)
end

local function errors_of(bufnr)
  return vim.diagnostic.get(bufnr, { severity = vim.diagnostic.severity.ERROR })
end

povrayst.setup({ cmd = { binary, 'lsp' } })

check('filetypes: scenes, includes that look like SDL, Typst documents', function()
  local cases = {
    { 'a.pov', { 'sphere { 0, 1 }' }, 'pov' },
    { 'b.mcr', { '' }, 'pov' },
    { 'c.inc', { '// shapes', '#declare R = 1;' }, 'pov' },
    { 'd.typ', { '= Title' }, 'typst' },
  }
  for _, case in ipairs(cases) do
    vim.cmd('edit ' .. write(case[1], case[2]))
    assert(vim.bo.filetype == case[3], case[1] .. ' has filetype ' .. vim.bo.filetype)
  end
  assert(not require('povrayst.filetype').looks_like_sdl({ '<?php include "x.inc"; ?>' }))
end)

check('a gallery scene with an injected error: the diagnostic text and position', function()
  local lines = vim.fn.readfile(gallery .. '/basic.pov')
  -- Line 14 of basic.pov is `  0, 1` in the sphere; misspell nothing else.
  assert(lines[14] == '  0, 1', 'basic.pov changed: ' .. lines[14])
  lines[14] = '  0, Radius'
  vim.cmd('edit ' .. write('basic.pov', lines))
  local bufnr = vim.api.nvim_get_current_buf()
  wait_for('diagnostics', function()
    return #errors_of(bufnr) > 0
  end)
  local diagnostic = errors_of(bufnr)[1]
  assert(diagnostic.message:find("^undeclared identifier 'Radius'"), diagnostic.message)
  assert(diagnostic.lnum == 13 and diagnostic.col == 5, ('at %d:%d'):format(diagnostic.lnum, diagnostic.col))
end)

check('hover on a keyword', function()
  vim.cmd('edit ' .. write('hover.pov', { '#version 3.7;', 'sphere { 0, 1 pigment { rgb 1 } }' }))
  local bufnr = vim.api.nvim_get_current_buf()
  wait_for('the server', function()
    return #vim.lsp.buf_get_clients(bufnr) > 0
  end)
  local params = {
    textDocument = { uri = vim.uri_from_bufnr(bufnr) },
    position = { line = 1, character = 2 },
  }
  local answers = vim.lsp.buf_request_sync(bufnr, 'textDocument/hover', params, 20000)
  local text
  for _, answer in pairs(answers or {}) do
    if answer.result then
      text = vim.inspect(answer.result.contents)
    end
  end
  assert(text and text:find('sphere'), 'hover: ' .. tostring(text))
end)

check('go to a #declare in an included file', function()
  write('parts.inc', { '// parts', '#declare Radius = 1.5;' })
  vim.cmd('edit ' .. write('goto.pov', { '#version 3.7;', '#include "parts.inc"', 'sphere { 0, Radius }' }))
  local bufnr = vim.api.nvim_get_current_buf()
  wait_for('the server', function()
    return #vim.lsp.buf_get_clients(bufnr) > 0
  end)
  vim.api.nvim_win_set_cursor(0, { 3, 13 })
  vim.lsp.buf.definition()
  wait_for('the jump', function()
    return vim.api.nvim_buf_get_name(0):find('parts%.inc$') ~= nil
  end)
  local cursor = vim.api.nvim_win_get_cursor(0)
  assert(cursor[1] == 2 and cursor[2] == 9, ('cursor at %d:%d'):format(cursor[1], cursor[2]))
end)

check('diagnostics inside a povray block of a Typst document', function()
  vim.cmd('edit ' .. write('doc.typ', {
    '= Scenes',
    '',
    '#render(```povray',
    '#version 3.7;',
    'sphere { 0, Size }',
    '```)',
  }))
  local bufnr = vim.api.nvim_get_current_buf()
  wait_for('diagnostics', function()
    return #errors_of(bufnr) > 0
  end)
  local diagnostic = errors_of(bufnr)[1]
  assert(diagnostic.message:find("^undeclared identifier 'Size'"), diagnostic.message)
  assert(diagnostic.lnum == 4 and diagnostic.col == 12, ('at %d:%d'):format(diagnostic.lnum, diagnostic.col))
end)

check(':PovrayRender writes a PNG beside the scene', function()
  vim.cmd('edit ' .. write('render.pov', {
    '#version 3.7;',
    'camera { location -3*z look_at 0 }',
    'light_source { <2, 2, -3>, rgb 1 }',
    'sphere { 0, 1 pigment { rgb 1 } }',
  }))
  local png = work .. '/render.png'
  local said
  vim.notify = function(message)
    said = message
  end
  vim.cmd('PovrayRender --width 16 --height 12')
  wait_for('the render to finish', function()
    return said ~= nil
  end)
  assert(said == 'PovrayRender: wrote ' .. png, said)
  local header = vim.fn.readfile(png, 'b', 1)[1]
  assert(header:find('PNG'), 'not a PNG')
end)

print(('%d passed, %d failed'):format(passed, failed))
vim.fn.delete(work, 'rf')
if failed > 0 then
  vim.cmd('cquit 1')
else
  vim.cmd('qall!')
end
