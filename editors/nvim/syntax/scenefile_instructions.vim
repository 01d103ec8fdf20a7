" Instruction files: OUTPUT_FILE, then START/END blocks of keyword lines.
if exists('b:current_syntax')
  finish
endif
syntax keyword scenefileInstructionsBlock START END
syntax keyword scenefileInstructionsSection CAMERA LIGHT OBJECT MATERIAL TRANSFORMATION
syntax keyword scenefileInstructionsKind PLANE SPHERE CYLINDER CUBE
syntax keyword scenefileInstructionsKey OUTPUT_FILE LOCATION LOOK_AT COLOUR AMBIENT DIFFUSE
      \ SPECULAR SHININESS REFLECTIVITY TRANSPARENCY RI
syntax keyword scenefileInstructionsOperation SCALE TRANSLATE ROTATE_X ROTATE_Y ROTATE_Z
" A number is a whole token: blanks or the line's ends on either side.
syntax match scenefileInstructionsNumber '\%(^\|\s\)\zs[+-]\=\%(\d\+\.\=\d*\|\.\d\+\)\%([eE][+-]\=\d\+\)\=\ze\%(\s\|$\)'
highlight default link scenefileInstructionsBlock Statement
highlight default link scenefileInstructionsSection Structure
highlight default link scenefileInstructionsKind Type
highlight default link scenefileInstructionsKey Keyword
highlight default link scenefileInstructionsOperation Function
highlight default link scenefileInstructionsNumber Number
let b:current_syntax = 'scenefile_instructions'
