# Standard input among several inputs: a usage error before any work, with
# or without -o.
cp S.sf a.sf && mkdir out
run $SFRENDER a.sf -
run $SFRENDER - a.sf
run $SFRENDER a.sf - -o 'out/{stem}.png'
absent a.ppm
run $SFCONVERT a.sf - -o 'out/{stem}.sf'
run $SFCONVERT - a.sf -o 'out/{stem}.sf'
ls out
temporaries
