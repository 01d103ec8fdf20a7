# Output names of 240 to 255 bytes, the longest a file system takes, in
# ASCII and in UTF-8 of 2, 3 and 4 bytes a character: each tool writes them
# (its temporary's name is shortened to fit), and leaves no temporary.
sfrender=${SFRENDER%% *}
# A name of $1 bytes ending in $3, made of the character $2 (and 'a' where
# a whole one does not fit).
name_of() {
  local bytes=$1 character=$2 extension=$3 name=""
  while (($(printf %s "$name$character$extension" | wc -c) <= bytes)); do name+=$character; done
  while (($(printf %s "$name$extension" | wc -c) < bytes)); do name+=a; done
  printf %s "$name$extension"
}
for character in a é € 😀; do
  written=0
  for bytes in 240 241 247 250 251 254 255; do
    png=$(name_of $bytes "$character" .png)
    sf=$(name_of $bytes "$character" .sf)
    gltf=$(name_of $bytes "$character" .gltf)
    $sfrender S.sf --width 4 --height 3 -q -o "$png" && [[ -s $png ]] && written=$((written + 1))
    $sfrender S.sf --width 40 --height 32 -q -o "${png%.png}.jpg" && written=$((written + 1))
    $SFCONVERT S.sf "$sf" -q && [[ -s $sf ]] && written=$((written + 1))
    # The .bin beside it is the .gltf's name with .bin: 1 byte shorter.
    $SFCONVERT S.sf "$gltf" --external-buffers -q && [[ -s ${gltf%.gltf}.bin ]] &&
      written=$((written + 1))
  done
  echo "$character: $written of 28 written"
done
temporaries
