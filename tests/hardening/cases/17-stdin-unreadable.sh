# Standard input that cannot be read (here a folder, EISDIR) is a file that
# could not be read, exit 3, with the reason: not an empty input.
mkdir folder
run bash -c "$SFCHECK - < folder"
run bash -c "$SFCONVERT - out.sf < folder"
run bash -c "$SFRENDER - -o out.ppm < folder"
absent out.sf
absent out.ppm
# An empty standard input is read, and is an empty file.
run bash -c "$SFCHECK - < /dev/null"
temporaries
