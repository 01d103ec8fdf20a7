# An option that takes one value, given twice (or more), is a usage error
# naming it, whichever the tool and the option: no output is guessed at.
run $SFRENDER S.sf -o x.png -o y.png
run $SFRENDER S.sf --output x.png -o x.png
run $SFRENDER S.sf --spp 4 --spp 5 -o z.ppm
run $SFRENDER S.sf --fov 30 --fov=40 --fov 50 -o z.ppm
run $SFRENDER S.sf --tile 0/2 --tile 1/2 -o z.ppm
absent x.png
absent y.png
absent z.ppm
run $SFCONVERT S.sf a.sf --to sf --to pov
run $SFCONVERT -o 'o/{stem}.sf' -o 'p/{stem}.sf' S.sf
absent a.sf
absent o
absent p
run $SFCHECK --format json --format text S.sf
run $SFCHECK --max-objects 5 --max-objects 6 S.sf
# Flags may be given twice: they say the same thing again.
run $SFCHECK -q -q S.sf
temporaries
