" Scene files by their extension; instruction files by their first non-blank
" line, OUTPUT_FILE, since their .txt says nothing (and Neovim has already
" called them "text", hence :set and not :setfiletype for them).
autocmd BufRead,BufNewFile *.sf setfiletype scenefile
autocmd BufRead,BufNewFile *
      \ if getline(nextnonblank(1)) =~# '^\%(\%xef\%xbb\%xbf\)\=\s*OUTPUT_FILE\>' |
      \   set filetype=scenefile_instructions |
      \ endif
