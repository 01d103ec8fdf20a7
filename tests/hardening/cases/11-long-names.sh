# Output names of 240 to 255 bytes, the longest a file system takes, in
# ASCII and in UTF-8 of 2, 3 and 4 bytes a character: each tool writes them
# (its temporary's name is shortened to fit), and leaves no temporary.
sfrender=${SFRENDER%% *}
# A name of $1 bytes ending in $3, made of the character $2 (and 'a' where
# a whole one does not fit).
bytes_of() { local LC_ALL=C text=$1; echo ${#text}; }
name_of() {
  local bytes=$1 character=$2 extension=$3 name=""
  local step=$(bytes_of "$character") fixed=$(bytes_of "$extension")
  while ((${#name} * step / ${#character} + step + fixed <= bytes)); do name+=$character; done
  while (($(bytes_of "$name$extension") < bytes)); do name+=a; done
  printf %s "$name$extension"
}
for character in a é € 😀; do
  written=0 lengths=""
  for bytes in 240 241 247 250 251 254 255; do
    png=$(name_of $bytes "$character" .png)
    lengths+=" $(bytes_of "$png")"
    sf=$(name_of $bytes "$character" .sf)
    gltf=$(name_of $bytes "$character" .gltf)
    $sfrender S.sf --width 4 --height 3 -q -o "$png" && [[ -s $png ]] && written=$((written + 1))
    $sfrender S.sf --width 40 --height 32 -q -o "${png%.png}.jpg" && written=$((written + 1))
    $SFCONVERT S.sf "$sf" -q && [[ -s $sf ]] && written=$((written + 1))
    # The .bin beside it is the .gltf's name with .bin: 1 byte shorter.
    $SFCONVERT S.sf "$gltf" --external-buffers -q && [[ -s ${gltf%.gltf}.bin ]] &&
      written=$((written + 1))
  done
  echo "$character: names of$lengths bytes: $written of 28 written"
done
temporaries
