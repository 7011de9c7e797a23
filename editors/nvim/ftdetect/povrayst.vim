" POV-Ray scenes and includes get Vim's `pov` filetype (its syntax highlighting, our
" language server). `.inc` is shared with other languages, so an include is taken as POV-Ray
" only when its first lines look like SDL. Typst documents get `typst`, for their povray blocks.
autocmd BufNewFile,BufRead *.pov,*.mcr,*.mac setlocal filetype=pov
autocmd BufNewFile,BufRead *.inc lua require('povrayst.filetype').detect_include()
autocmd BufNewFile,BufRead *.typ setfiletype typst
