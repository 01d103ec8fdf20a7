# A tile named twice is two regions that agree where they overlap: the
# image, wherever and however often the name comes again.
$SFRENDER S.sf --tile 0/2 -q -o top.exr
$SFRENDER S.sf --tile 1/2 -q -o bottom.exr
$SFRENDER S.sf -q -o whole.png
run $SFRENDER --merge top.exr bottom.exr top.exr -o a.png
same a.png whole.png
run $SFRENDER --merge top.exr top.exr bottom.exr -q -o b.png
same b.png whole.png
run $SFRENDER --merge bottom.exr top.exr ./bottom.exr bottom.exr -q -o c.png
same c.png whole.png
temporaries
