# A batch that would write over any of its inputs, even one it reads later,
# is refused (exit 2) before anything is written; the inputs stay as they
# were.
cp S.sf p.sf
$SFCONVERT S.sf px.txt -q && cp px.txt px.kept
run $SFCONVERT p.sf px.txt -o '{dir}/{stem}x.txt'
run $SFCONVERT px.txt p.sf -o '{dir}/{stem}x.txt'
same px.txt px.kept
absent pxx.txt
run $SFCONVERT p.sf px.txt -o '{dir}/{name}'
run $SFCONVERT p.sf px.txt -o './{stem}.sf'
same p.sf S.sf
# sfrender: a scene file named like another's image.
cp S.sf a.sf && cp S.sf b.png
run $SFRENDER a.sf b.png -o '{stem}.png'
run $SFRENDER a.sf b.png -o '{dir}/b.png'
absent a.png
same b.png S.sf
# No -o: an OUTPUT_FILE that names another input, and a scene that is its
# own default image.
cp S.sf s.ppm
sed 's/^OUTPUT_FILE .*/OUTPUT_FILE s.ppm/' px.txt >i.txt
run $SFRENDER i.txt s.ppm
same s.ppm S.sf
# The glTF buffer of one output is another input.
cp S.sf g.sf && cp S.sf g.bin
run $SFCONVERT g.sf g.bin -o '{stem}' --to gltf --external-buffers
same g.bin S.sf
absent g
temporaries
