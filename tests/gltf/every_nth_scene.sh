# Sourced by the glTF interop tests. keep_every_nth_scene FOLDER: leaves
# every EVERY_NTH_SCENE-th file of FOLDER (default 1, all of them), in the
# order of the glob.
keep_every_nth_scene() {
  local every=${EVERY_NTH_SCENE:-1} n=0 input
  for input in "$1"/*; do
    n=$((n + 1))
    ((n % every == 0)) || rm "$input"
  done
}
