# No render writes a NaN or an infinity, so a tile that holds one is
# refused (exit 1), naming the file and the pixel, and nothing is written.
$SFRENDER S.sf --tile 0/2 -q -o top.exr
$SFRENDER S.sf --tile 1/2 -q -o bottom.exr
for value in nan inf -inf; do
  oiiotool bottom.exr --fill:color=0,0,$value 1x1+5+8 -d float -o "t$value.exr"
  run $SFRENDER --merge top.exr "t$value.exr" -o m.png
done
oiiotool top.exr --fill:color=nan,nan,nan 2x2+0+0 -d float -o first.exr
run $SFRENDER --merge first.exr bottom.exr -o m.tif
absent m.png
absent m.tif
temporaries
