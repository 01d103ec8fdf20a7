# Two inputs onto one output, however they and it are spelled: refused
# (exit 2) before anything is written, naming both inputs and the output.
mkdir x y z out
cp S.sf x/a.sf && cp S.sf x/a.txt
run $SFRENDER x/a.sf x/./a.txt -o '{dir}/{stem}.png'
run $SFRENDER x/a.sf "$PWD/x/a.txt" -o '{dir}/{stem}.png' | sed "s#$PWD#PWD#g"
ln -s x linked
run $SFRENDER x/a.sf linked/a.txt -o '{dir}/{stem}.png'
run $SFRENDER x/a.sf x//a.txt -o '{dir}/{stem}.png'
absent x/a.png
# The same file twice.
run $SFRENDER x/a.sf x/../x/a.sf -o 'out/{name}.png'
absent out/a.sf.png
# Outputs that already are one file: a hard link, a symbolic link.
cp S.sf p.sf && cp S.sf q.sf && echo old >out/p.png && ln out/p.png out/q.png
run $SFRENDER p.sf q.sf -o 'out/{stem}.png'
rm out/q.png && ln -s p.png out/q.png
run $SFRENDER p.sf q.sf -o 'out/{stem}.png'
cat out/p.png
# No -o: two s.sf in two folders would both write s.png here.
cp S.sf y/s.sf && cp S.sf z/s.sf
run $SFRENDER y/s.sf z/s.sf
absent s.png
# Instruction files whose OUTPUT_FILEs land on one file.
$SFCONVERT S.sf y/i.txt -q
sed -i 's/^OUTPUT_FILE .*/OUTPUT_FILE pic.png/' y/i.txt
cp y/i.txt y/j.txt
run $SFRENDER y/i.txt y/j.txt
absent y/pic.png
sed 's/^OUTPUT_FILE .*/OUTPUT_FILE s.png/' y/i.txt >k.txt
run $SFRENDER k.txt z/s.sf -q
absent s.png
# sfconvert: one output for two inputs, and glTF buffers shared.
run $SFCONVERT x/a.sf x/a.txt -o 'out/{stem}.sf'
cp S.sf m.x.sf && cp S.sf m.y.sf
run $SFCONVERT m.x.sf m.y.sf -o 'out/{stem}' --to gltf --external-buffers
cp S.sf c.sf && cp S.sf c.bin
run $SFCONVERT c.sf c.bin -o 'out/{name}' --to gltf --external-buffers
ls out
temporaries
