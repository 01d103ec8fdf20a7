# The harness itself: a valid render, and a missing input.
run $SFRENDER S.sf -o out.png -q
present out.png
run $SFCHECK missing.sf
temporaries
