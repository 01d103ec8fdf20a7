# A field of view or an image size that no file written with it would read
# back (or that sfrender cannot render) is refused at the command line, with
# the range; the ends of the range give files that read back with that view
# (the hint sfcheck prints).
for format in pov gltf glb; do
  for value in 1e-300 4.9e-324 0 0.0009 179.9991 180; do
    run $SFCONVERT S.sf "out.$format" --fov "$value"
  done
  absent "out.$format"
  for value in 0.001 179.999; do
    run $SFCONVERT -q S.sf "fov-$value.$format" --fov "$value"
    run $SFCHECK -q "fov-$value.$format"
    $SFCHECK -v "fov-$value.$format" 2>&1 | grep -o 'render with sfrender.*'
  done
  run $SFCONVERT S.sf "wide.$format" --width 32769 --height 1
  run $SFCONVERT S.sf "tall.$format" --height 32769
  run $SFCONVERT -q S.sf "wide.$format" --width 32768 --height 1
  run $SFCHECK -q "wide.$format"
  $SFCHECK -v "wide.$format" 2>&1 | grep -o 'render with sfrender.*'
  run $SFCONVERT -q S.sf "tall.$format" --width 1 --height 32768
  run $SFCHECK -q "tall.$format"
  run $SFCONVERT -q S.sf "tall-default.$format" --height 32768
  run $SFCHECK -q "tall-default.$format"
done
for value in 2 1025 1e-310; do
  run $SFCONVERT S.sf t.glb --tessellation "$value"
done
run $SFCONVERT -q S.sf t.glb --tessellation 3
run $SFCHECK -q t.glb
run $SFRENDER S.sf --fov 1e-300 -o x.ppm
run $SFRENDER S.sf --width 32769 -o x.ppm
absent x.ppm
temporaries
