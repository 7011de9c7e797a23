-- Deciding whether an `.inc` file is POV-Ray: Pascal, PHP and BitBake use the extension
-- too, so look for SDL directives in the first lines before claiming it.
local M = {}

local sdl_line = {
  '^%s*#%s*declare%s',
  '^%s*#%s*local%s',
  '^%s*#%s*macro%s',
  '^%s*#%s*include%s+"',
  '^%s*#%s*ifndef%s*%(',
  '^%s*#%s*version%s',
}

function M.looks_like_sdl(lines)
  for _, line in ipairs(lines) do
    for _, pattern in ipairs(sdl_line) do
      if line:find(pattern) then
        return true
      end
    end
  end
  return false
end

function M.detect_include()
  if M.looks_like_sdl(vim.api.nvim_buf_get_lines(0, 0, 200, false)) then
    vim.bo.filetype = 'pov'
  end
end

return M
