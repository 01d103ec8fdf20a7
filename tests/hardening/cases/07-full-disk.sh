# An image onto a full file system, in every format sfrender writes (the
# extensions of its own --help) and from --merge: exit 3, the old image kept
# byte for byte, no temporary. A small tmpfs of the case's own (root only),
# filled so that the new image only partly fits: half its size is left.
[[ $(id -u) == 0 ]] || skip "needs root, to mount a tmpfs"
mkdir disk
mount -t tmpfs -o size=4m tmpfs disk 2>/dev/null || skip "cannot mount a tmpfs"
trap 'umount disk' EXIT
sfrender=${SFRENDER%% *}
small=(--width 40 --height 32)
big=(--width 320 --height 240)

# Leaves at most `bytes` of room on the tmpfs, in whole pages (none for
# less than one), the rest taken by disk/fill.
leave() {
  rm -f disk/fill
  local free
  free=$(df --output=avail -B1 disk | tail -1)
  fallocate -l $(((free - $1 + 4095) / 4096 * 4096)) disk/fill
}
# Runs the command over disk/$target, which holds an older image, with
# half the new image's room; prints one line of what held.
over_full_disk() {
  local target=$1 bytes=$2 status=0
  shift 2
  cp "disk/$target" old
  leave $((bytes / 2))
  "$@" >out.txt 2>&1 || status=$?
  echo "$target: exit $status, $(same "disk/$target" old), $(cd disk && temporaries)"
  sed -E 's/[0-9]+/N/g' out.txt | sort -u
  rm -f disk/fill
}

# One line of extensions a format, from sfrender's own --help: each format's
# new image is measured once, each of its extensions written over the full
# disk.
formats=$($sfrender --help | sed -n '/^  extensions/,/^  The first/p' | sed '1d;$d' |
  sed -E 's/^  ((\.[a-z0-9]+ )*\.[a-z0-9]+)  .*/\1/')
while read -r -a extensions; do
  first=${extensions[0]}
  $sfrender S.sf "${small[@]}" -q -o "old$first" || echo "cannot write a small $first"
  $sfrender S.sf "${big[@]}" -q -o "new$first" || echo "cannot write a big $first"
  for ext in "${extensions[@]}"; do
    cp "old$first" "disk/keep$ext"
    over_full_disk "keep$ext" "$(stat -c %s "new$first")" $sfrender S.sf "${big[@]}" -o "disk/keep$ext"
    rm -f "disk/keep$ext"
  done
done <<<"$formats"

# --merge: its image, onto the full disk too.
$sfrender S.sf "${big[@]}" --tile 0/2 -q -o top.exr
$sfrender S.sf "${big[@]}" --tile 1/2 -q -o bottom.exr
$sfrender --merge top.exr bottom.exr -q -o m.bmp
$sfrender S.sf "${small[@]}" -q -o disk/m.bmp
over_full_disk m.bmp "$(stat -c %s m.bmp)" $sfrender --merge top.exr bottom.exr -o disk/m.bmp
