# --merge takes its image's size from a tile's display window: bounded by
# --max-pixels, as a render is, and checked with the data window and the
# channels before anything is allocated.
sfrender=${SFRENDER%% *}
$sfrender S.sf --width 1 --height 1 -q -o one.exr
box() { python3 "$SOURCE/tests/hardening/exr_window.py" "$@"; }
box one.exr displayWindow wide.exr -536870912 0 536870911 0  # 2^30 x 1
box one.exr displayWindow big.exr 0 0 65535 16383             # 2^30 pixels
box one.exr dataWindow outside.exr 5 0 5 0
box one.exr dataWindow above.exr 0 -3 0 -3
# Refused at once (02-merge-windows-memory: in 1 GiB of address space).
run $sfrender --merge wide.exr -o m.png
run $sfrender --merge big.exr -o m.png
run $sfrender --merge outside.exr -o m.png
run $sfrender --merge one.exr above.exr -o m.png
oiiotool --create 2x2 5 -d float -o five.exr
run $sfrender --merge five.exr -o m.png
# A whole image's tiles within the limit, and one pixel over it.
$SFRENDER S.sf --tile 0/2 -q -o top.exr
$SFRENDER S.sf --tile 1/2 -q -o bottom.exr
run $sfrender --merge top.exr bottom.exr -o m.png --max-pixels 191
absent m.png
run $sfrender --merge top.exr bottom.exr -o m.png --max-pixels 192 -q
present m.png
temporaries
