# Standard input has no name: no placeholder of it expands (exit 2).
mkdir out
stdin() { "$@" <S.sf 2>&1; echo "exit $?"; }
stdin $SFRENDER - -o 'out/{stem}.png'
stdin $SFRENDER - -o 'out/{name}.png'
stdin $SFRENDER - -o '{dir}/x.png'
stdin $SFCONVERT - -o 'out/{stem}.sf'
ls out
absent out/-.png
# Named, it is read.
stdin $SFRENDER - -o out/named.png -q
present out/named.png
temporaries
