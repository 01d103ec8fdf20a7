# An instruction file written under a name that OUTPUT_FILE cannot hold
# (a blank, a tab, a newline, a character that is not ASCII): its
# OUTPUT_FILE has '_' in their place, sfconvert says so, and the file reads
# back.
for name in 'my scene.txt' $'tab\t.txt' $'new\nline.txt' 'café.txt' '{stem}.txt' 'plain.txt'; do
  run $SFCONVERT S.sf "$name"
  head -n 1 -- "$name"
  run $SFCHECK -q -- "$name"
done
# A batch names each output's image the same way.
mkdir out
cp S.sf 'a b.sf'
run $SFCONVERT -o 'out/{stem}.txt' 'a b.sf'
head -n 1 -- 'out/a b.txt'
run $SFCHECK -q -- 'out/a b.txt'
# The image rendered from such a file is the name it reads.
run $SFRENDER -q 'my scene.txt'
present my_scene.ppm
temporaries
