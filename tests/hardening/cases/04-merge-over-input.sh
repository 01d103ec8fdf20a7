# --merge never writes over one of its tiles, however the output is spelled;
# the tiles are kept as they were.
sfrender=${SFRENDER%% *}
$SFRENDER S.sf --tile 0/2 -o a.exr -q
$SFRENDER S.sf --tile 1/2 -o b.exr -q
cp a.exr a.kept && cp b.exr b.kept
mkdir x && ln a.exr hard.exr && ln -s b.exr link.exr
run $sfrender --merge a.exr b.exr -o a.exr
run $sfrender --merge a.exr b.exr -o ./b.exr
run $sfrender --merge a.exr b.exr -o x/../b.exr
run $sfrender --merge a.exr b.exr -o "$PWD/a.exr" | sed "s#$PWD#PWD#"
run $sfrender --merge a.exr b.exr -o hard.exr
run $sfrender --merge a.exr b.exr -o link.exr
run $sfrender --merge hard.exr b.exr -o a.exr --no-clobber
same a.exr a.kept
same b.exr b.kept
# A new file is no tile: merged.
run $sfrender --merge a.exr b.exr -o merged.exr
present merged.exr
temporaries
