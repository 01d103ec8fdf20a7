# A placeholder never becomes a path step: {stem} and {name} that would be
# '', '.' or '..' refuse the input (exit 2, nothing written); {dir} may climb
# with '..' only at the start of the pattern.
mkdir -p out/sub
cp S.sf ...sf && cp S.sf ..sf && cp S.sf a.sf && cp S.sf ...
run $SFRENDER ...sf -o 'out/sub/{stem}/x.ppm'
run $SFRENDER a.sf ...sf -o 'out/sub/{stem}/x.ppm'
run $SFRENDER ..sf -o 'out/sub/{stem}/x.ppm'
run $SFCONVERT ... -o 'out/sub/{stem}/x.sf'
run $SFCONVERT a.sf out/sub/.. -o 'out/{name}.sf'
run $SFCONVERT out/ -o 'out/{name}.sf'
absent out/x.ppm
absent out/sub/x.ppm
absent out/x.sf
# {dir} after a fixed folder may not climb out of it.
mkdir -p in/deep
cp S.sf in/b.sf
run $SFRENDER in/../a.sf -o 'out/{dir}/{stem}.ppm'
run $SFCONVERT in/deep/../../a.sf in/b.sf -o 'out/{dir}/{stem}.sf'
mkdir w && cd w && mkdir out
run $SFRENDER ../a.sf -o 'out/{dir}/{stem}.ppm'
absent ../a.ppm
# At the start of the pattern, {dir} is the input's own folder.
run $SFRENDER ../a.sf ../in/b.sf -o '{dir}/{stem}.ppm' -q
present ../a.ppm
present ../in/b.ppm
# Names of dots that are names: {name} of '...' and {stem} of '.sf'.
cd .. && cp S.sf .sf
run $SFCONVERT ... .sf -o 'out/{name}-x.sf' -q
run $SFCONVERT .sf -o 'out/{stem}.y.sf' -q
ls -A out
temporaries
