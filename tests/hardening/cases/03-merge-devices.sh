# --merge reads regular files only: a device, a pipe or a folder is refused
# at once, before it is opened (/dev/zero would be read for ever, a pipe
# would wait for a writer). Each run is cut off after 10 s.
sfrender=${SFRENDER%% *}
$SFRENDER S.sf --tile 0/2 -q -o top.exr
$SFRENDER S.sf --tile 1/2 -q -o bottom.exr
mkfifo pipe.exr
mkdir folder.exr
ln -s /dev/zero zero.exr
run timeout 10 $sfrender --merge /dev/zero -o m.png
run timeout 10 $sfrender --merge top.exr zero.exr -o m.png
run timeout 10 $sfrender --merge top.exr pipe.exr -o m.png
run timeout 10 $sfrender --merge top.exr folder.exr -o m.png
run timeout 10 $sfrender --merge top.exr /dev/stdin -o m.png
absent m.png
temporaries
