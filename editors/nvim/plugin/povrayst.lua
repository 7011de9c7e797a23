-- :PovrayRender renders the current scene with `povrayst render`; the language server is
-- started by require('povrayst').setup() (or through nvim-lspconfig), not here.
vim.api.nvim_create_user_command('PovrayRender', function(command)
  require('povrayst').render(command.fargs)
end, { nargs = '*', desc = 'Render the current POV-Ray scene to a PNG beside it' })
