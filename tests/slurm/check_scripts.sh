#!/bin/bash
# The Slurm scripts' command lines without a cluster: an `sbatch` of this
# test's own, first on PATH, records each call and runs the job at once on
# this machine (an array's tasks one after the other, a job whose afterok
# dependency failed not at all), so that what the scripts submit is seen
# and what it makes is checked. Flags that cannot work with tiles are
# refused before anything is submitted; those of the merged image reach
# the merge; a list of scenes is read as lines, CRLF ones too.
# Arguments: BIN_DIR (sfrender, sfgen) SOURCE_DIR.
set -uo pipefail
bin=$1 source=$2
work=$(mktemp -d /tmp/sfslurm-scripts.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

mkdir fake
cat >fake/sbatch <<'EOF'
#!/bin/bash
# Records the call (one line, each argument quoted) and runs the job here.
printf '%q ' "$@" >>"$SBATCH_LOG"
echo >>"$SBATCH_LOG"
id=$(($(wc -l <"$SBATCH_LOG") + 100))
array='' output='' export_dir='' dependency=''
while [[ $1 == -* ]]; do
  case $1 in
    --array=*) array=${1#*=} ;;
    --output=*) output=${1#*=} ;;
    --export=*) export_dir=${1#*SFSLURM_DIR=} ;;
    --dependency=afterok:*) dependency=${1#*afterok:} ;;
  esac
  shift
done
if [[ -n $dependency && -e $SBATCH_LOG.failed-$dependency ]]; then echo "$id"; exit 0; fi
first=0 last=0
[[ -n $array ]] && first=${array%-*} last=${array#*-}
for ((task = first; task <= last; ++task)); do
  log=${output//%a/$task}
  log=${log//%A/$id}
  SFSLURM_DIR=$export_dir SLURM_ARRAY_JOB_ID=$id SLURM_ARRAY_TASK_ID=$task \
    bash "$@" >>"${log:-/dev/null}" 2>&1 || touch "$SBATCH_LOG.failed-$id"
done
echo "$id"
EOF
chmod +x fake/sbatch
export PATH="$work/fake:$PATH" SBATCH_LOG="$work/sbatch.log"
tiles="$source/scripts/slurm/sfrender-tiles.sh"
batch="$source/scripts/slurm/sfbatch.sh"
"$bin/sfgen" --layout floor -n 20 -s 1 -o scene.sf >/dev/null || exit 1
size=(--width 32 --height 18)

# $1: the expected exit status; the rest, the command. Its standard error
# is kept in err.txt.
expect() {
  local want=$1 status=0
  shift
  : >"$SBATCH_LOG"
  "$@" >out.txt 2>err.txt || status=$?
  if ((status != want)); then
    fail "$* exited $status, not $want: $(cat err.txt)"
    return 1
  fi
}
# $1: a word the refusal must name; the rest, the command, which must exit 2
# having submitted nothing.
refused() {
  local word=$1
  shift
  expect 2 "$@" || return
  grep -qF -- "$word" err.txt || fail "$* did not name $word: $(cat err.txt)"
  [[ ! -s $SBATCH_LOG ]] || fail "$* submitted: $(cat "$SBATCH_LOG")"
}

# Flags that tiles cannot carry.
s=(bash "$tiles" scene.sf --sfrender "$bin/sfrender" --tiles 3 "${size[@]}")
refused --alpha "${s[@]}" -o a.png --alpha
refused --region "${s[@]}" -o a.png --region 0,0,4,4
refused --region "${s[@]}" -o a.png --region=0,0,4,4
refused --tile "${s[@]}" -o a.png --tile 0/2
refused --merge "${s[@]}" -o a.png --merge
refused "given twice" "${s[@]}" -o a.png -o b.png
refused "exclude" "${s[@]}" -o a.png -q -v
refused "{stem}" "${s[@]}" -o '{stem}.png'
# The merge's own refusals, found before the tiles are rendered.
refused "--bits" "${s[@]}" -o a.png --bits 12
refused "--bits" "${s[@]}" -o a.jpg --bits 16
[[ ! -e a.png.tiles && ! -e a.jpg.tiles ]] || fail "a refusal made the work folder"

# --bits reaches the merge, the tiles staying float EXR: a 16-bit PNG.
if expect 0 "${s[@]}" -o a.png --bits 16; then
  grep -q -- "--bits" <(head -n 1 "$SBATCH_LOG") && fail "the tiles were given --bits"
  grep -q -- "--bits 16" <(tail -n 1 "$SBATCH_LOG") || fail "the merge was not given --bits 16"
  depth=$(od -An -tu1 -j24 -N1 a.png 2>/dev/null | tr -d ' ')
  [[ $depth == 16 ]] || fail "a.png has $depth bits a channel, not 16: $(cat a.png.tiles/merge.log)"
fi
# -v reaches both, and the tiles, quiet by default, are not told both.
if expect 0 "${s[@]}" -o v.png -v; then
  [[ -s v.png ]] || fail "-v: no v.png; tile 0's log: $(cat v.png.tiles/tile-0.log)"
  grep -q "wrote" v.png.tiles/merge.log || fail "-v: the merge was not verbose"
fi
# --no-clobber: an existing image is kept, before anything is submitted.
echo keep >kept.png
if expect 3 "${s[@]}" -o kept.png --no-clobber && [[ -s $SBATCH_LOG ]]; then
  fail "--no-clobber over an existing image was submitted"
fi
[[ $(cat kept.png) == keep ]] || fail "--no-clobber: kept.png was replaced"

# A list written with CRLF line ends, a blank line and a comment.
mkdir -p scenes out
for seed in 1 2 3; do "$bin/sfgen" --layout floor -n 10 -s "$seed" -o "scenes/s$seed.sf" >/dev/null; done
printf 'scenes/s1.sf\r\n\r\n# not a scene\r\nscenes/s2.sf\r\nscenes/s3.sf' >list.txt
b=(bash "$batch" list.txt --sfrender "$bin/sfrender" --logs logs "${size[@]}" -q)
if expect 0 "${b[@]}" -o 'out/{stem}.png' --tasks 2; then
  grep -q -- "--array=0-1" "$SBATCH_LOG" || fail "two tasks were not asked for: $(cat "$SBATCH_LOG")"
  for seed in 1 2 3; do
    [[ -s out/s$seed.png ]] || fail "the CRLF list: out/s$seed.png is missing: $(cat logs/*)"
  done
fi
refused --merge "${b[@]}" -o 'out/{stem}.png' --merge
refused "given twice" "${b[@]}" -o 'out/{stem}.png' -o 'x/{stem}.png'
printf '\r\n# only a comment\r\n' >empty.txt
expect 1 bash "$batch" empty.txt -o 'out/{stem}.png' --sfrender "$bin/sfrender"

if ((failures > 0)); then
  echo "$failures failures" >&2
  exit 1
fi
echo "PASS: the Slurm scripts refuse what tiles cannot do, carry the rest, and read CRLF lists"
