# A tile's display window is refused before anything is allocated: in 1
# GiB of address space. Not under the sanitizers, whose shadow memory no
# address-space limit holds.
needs_address_space_limits
sfrender=${SFRENDER%% *}
$sfrender S.sf --width 1 --height 1 -q -o one.exr
box() { python3 "$SOURCE/tests/hardening/exr_window.py" "$@"; }
box one.exr displayWindow wide.exr -536870912 0 536870911 0  # 2^30 x 1
box one.exr displayWindow big.exr 0 0 65535 16383             # 2^30 pixels
(ulimit -v 1048576 && run $sfrender --merge wide.exr -o m.png)
(ulimit -v 1048576 && run $sfrender --merge big.exr -o m.png)
# The limit is --max-pixels: raised, the merge goes on to allocate (and here
# runs out of the address space it has).
(ulimit -v 1048576 && run $sfrender --merge big.exr -o m.png --max-pixels 1073741824 -q)
temporaries
