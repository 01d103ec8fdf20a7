" Scene files (.sf): records of six lines, a name then numbers.
if exists('b:current_syntax')
  finish
endif
syntax keyword scenefileRecord CAMERA LIGHT PLANE SPHERE CYLINDER CUBE
" A number is a whole token: blanks or the line's ends on either side.
syntax match scenefileNumber '\%(^\|\s\)\zs[+-]\=\%(\d\+\.\=\d*\|\.\d\+\)\%([eE][+-]\=\d\+\)\=\ze\%(\s\|$\)'
highlight default link scenefileRecord Keyword
highlight default link scenefileNumber Number
let b:current_syntax = 'scenefile'
