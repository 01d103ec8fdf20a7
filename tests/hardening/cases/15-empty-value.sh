# --opt= with nothing after the '=' is an empty value, refused: never a way
# to take the next argument as the value.
run $SFRENDER S.sf --width= 5 -o a.ppm
run $SFRENDER S.sf --fov= -o a.ppm
run $SFRENDER S.sf --adaptive= 0.5 -o a.ppm
run $SFRENDER S.sf --output= a.ppm
run $SFRENDER S.sf -o '' --seed=
run $SFRENDER S.sf --tile= 0/2 -o a.ppm
run $SFRENDER S.sf --device= cpu -o a.ppm
run $SFRENDER S.sf --bits= 8 -o a.png
absent a.ppm
absent a.png
run $SFCONVERT S.sf b.gltf --tessellation=
run $SFCONVERT S.sf b.gltf --to= gltf
run $SFCONVERT S.sf --output= b.gltf
run $SFCONVERT S.sf b.gltf --max-file-size=
absent b.gltf
run $SFCHECK --max-objects= 5 S.sf
run $SFCHECK --format= json S.sf
run $SFCHECK --color= S.sf
# After "--" a word ending in '=' is an argument like any other.
run $SFCHECK -- --width=
temporaries
