# Numbers at the edges of a double, and text that is no number, given to the
# numeric options of every tool: the number the text is, or a usage error
# naming the option and the value. Never an abort.
run $SFRENDER S.sf --adaptive 1e-310 --spp 4 -o a.ppm
present a.ppm
run $SFRENDER S.sf --adaptive 4.9e-324 --spp 4 -o b.ppm
present b.ppm
for value in 1e-400 0 -0 nan inf 1e400 0x1p-3 ' 0.5' ''; do
  run $SFRENDER S.sf --adaptive "$value" -o c.ppm
done
absent c.ppm
# A leading 0 is decimal, not octal: --width 010 is 10 pixels (CLI11's own
# conversion read 8, and refused 08 and 09).
run $SFCONVERT -q S.sf d.pov --width 010 --height 09
grep -o 'width [0-9]* height [0-9]*' d.pov
for option in --fov --width --height --spp --depth --threads --seed --max-pixels --max-spp \
  --max-depth --max-objects --max-vertices --max-nodes --max-file-size; do
  for value in 1e-310 nan -inf 99999999999999999999 0x10; do
    run $SFRENDER S.sf "$option" "$value" -o e.ppm
  done
done
absent e.ppm
for option in --fov --width --height --tessellation --max-objects --max-file-size; do
  for value in 4.9e-324 1e400 abc; do
    run $SFCONVERT S.sf "$option" "$value" f.gltf
  done
done
absent f.gltf
for option in --max-objects --max-vertices --max-nodes --max-file-size; do
  run $SFCHECK "$option" 1e-310 S.sf
  run $SFCHECK "$option" 010 S.sf
done
run $SFCHECK --max-file-size 8EiB S.sf
temporaries
