#!/usr/bin/env bash
# assimp (Debian's assimp-utils) reads what sfconvert writes as OBJ: for
# each scene, `assimp info` reports one mesh per object, one material per
# distinct MTL material (it merges equal ones), the file's faces and at most
# its vertices (it welds equal ones), and `assimp export` to PLY writes
# every triangle (three vertices each: export does not weld). Exit 77
# (skipped) without assimp.
#
# Usage: check_assimp.sh SFCONVERT WORK_DIR SCENE...
set -euo pipefail
sfconvert=$1
work=$2
shift 2
command -v assimp >/dev/null || { echo "assimp is not installed: skipped"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail=0
# The value of `assimp info`'s line "NAME: value".
info_value() { grep -E "^$1: " info.txt | head -n 1 | sed -E 's/^[^:]*: *//'; }
for scene in "$@"; do
  name=$(basename "${scene%.*}")
  "$sfconvert" -q "$scene" "$name.obj" 2>/dev/null
  [ -f "$name.mtl" ] || { echo "$name: no $name.mtl beside $name.obj"; fail=1; continue; }
  objects=$(grep -c '^o ' "$name.obj" || true)
  vertices=$(grep -c '^v ' "$name.obj" || true)
  faces=$(grep -c '^f ' "$name.obj" || true)
  # The MTL blocks without their names, each on one line, told apart.
  materials=$(awk '/^newmtl/ { if (b != "") print b; b = ""; next } NF { b = b $0 ";" }
                   END { if (b != "") print b }' "$name.mtl" | sort -u | wc -l)
  assimp info "$name.obj" >info.txt 2>&1 || { echo "$name: assimp info failed"; cat info.txt; fail=1; continue; }
  for check in "Meshes $objects" "Materials $materials" "Faces $faces"; do
    set -- $check
    got=$(info_value "$1")
    if [ "$got" != "$2" ]; then
      echo "$name: assimp info says $1: $got, the file has $2"
      fail=1
    fi
  done
  welded=$(info_value Vertices)
  if [ -z "$welded" ] || [ "$welded" -gt "$vertices" ] || [ "$welded" -lt 1 ]; then
    echo "$name: assimp info says Vertices: $welded, the file has $vertices"
    fail=1
  fi
  assimp export "$name.obj" "$name.ply" >export.txt 2>&1 || { echo "$name: assimp export failed"; cat export.txt; fail=1; continue; }
  ply_vertices=$(grep -a -m1 '^element vertex ' "$name.ply" | cut -d' ' -f3)
  ply_faces=$(grep -a -m1 '^element face ' "$name.ply" | cut -d' ' -f3)
  if [ "$ply_faces" != "$faces" ] || [ "$ply_vertices" != "$((3 * faces))" ]; then
    echo "$name: the PLY has $ply_vertices vertices and $ply_faces faces;" \
      "expected $((3 * faces)) and $faces"
    fail=1
  fi
  echo "$name: $objects meshes, $materials materials, $faces faces, $welded of $vertices" \
    "vertices welded; PLY $ply_vertices vertices"
done
exit $fail
