#!/usr/bin/env bash
# The SIGKILL test: a tool killed at any moment leaves its old output or its
# new one, never a part of either (tools/common/file_io.h).
#
#   sigkill_test.sh BIN_DIR SFGEN WORK_DIR
#
# Three writers, in turn, each over an older output of its own:
#   convert  sfconvert of a generated scene file (sfgen, 200,000 objects,
#            24 MB) to .sf
#   ppm      sfrender writing a 2000 x 1500 PPM (9 MB; SIGKILL_IMAGE) of a
#            sphere on a plane
#   png      sfrender writing the same image as PNG (through OpenImageIO)
# Each run is killed with SIGKILL after a random delay, and the target must
# then be byte for byte the old output or the new one (a reference written
# once by a run left alone). Where the kill landed is read from what it left:
# the writer's temporary still there (.NAME.tmp-XXXXXX...) means it landed in
# the write window, between the temporary's creation and its rename, and then
# the target must still be the old file; otherwise the target tells whether
# it landed before the write or after the rename.
#
# The kills concentrate on the write window: a calibration run per writer
# times its run and its window (while the temporary is there), and every run
# that ends before its kill corrects those times; 60% of the kills come a
# random delay after the temporary appears, up to the window's length (and
# 2 ms), and the other 40% a random delay after the start, anywhere up to
# 1.05 times the run's length.
#
# SIGKILL_ITERATIONS (default 100) kills in a row, across the three writers;
# SIGKILL_OBJECTS (200000) the generated scene's size, SIGKILL_IMAGE
# (2000x1500) the render's.
set -euo pipefail

bin=${1:?usage: sigkill_test.sh BIN_DIR SFGEN WORK_DIR}
sfgen=${2:?usage: sigkill_test.sh BIN_DIR SFGEN WORK_DIR}
work=${3:?usage: sigkill_test.sh BIN_DIR SFGEN WORK_DIR}
iterations=${SIGKILL_ITERATIONS:-100}
objects=${SIGKILL_OBJECTS:-200000}
image=${SIGKILL_IMAGE:-2000x1500}

rm -rf "$work"
mkdir -p "$work"
cd "$work"

as_seconds() { printf '%d.%06d' $(($1 / 1000000)) $(($1 % 1000000)); }
# The same into the variable named $1, without a subshell.
to_seconds() { printf -v "$1" '%d.%06d' $(($2 / 1000000)) $(($2 % 1000000)); }
# A random integer in [low, high).
random_between() {
  local low=$1 high=$2
  ((high > low)) || high=$((low + 1))
  echo $((low + (RANDOM * 32768 + RANDOM) % (high - low)))
}

# The writers: the command writing the new output, the one writing the old.
"$sfgen" -n "$objects" -s 11 -o big.sf >/dev/null
"$sfgen" -n 50 -s 12 -o small.sf >/dev/null
# The image: cheap to render (two objects), not so cheap to compress.
cat >scene.sf <<'EOF'
CAMERA
0 0 0
1 0 0 0
0 1 0 0
0 0 1 5
0 0 0 1
LIGHT
1 1 1
1 0 0 3
0 1 0 3
0 0 1 3
0 0 0 1
SPHERE
1 0.5 0.2
2 0 0 0
0 2 0 0
0 0 2 0
0 0 0 1
PLANE
0.2 0.6 0.3
1 0 0 0
0 1 0 -1
0 0 1 0
0 0 0 1
EOF
render=(--width "${image%x*}" --height "${image#*x}" --spp 1 --depth 2 --quiet)
small=(--width 64 --height 48 --quiet)
declare -A new_command old_command target
target[convert]=convert.sf
new_command[convert]="$bin/sfconvert big.sf convert.sf"
old_command[convert]="$bin/sfconvert small.sf convert.sf"
target[ppm]=render.ppm
new_command[ppm]="$bin/sfrender scene.sf -o render.ppm ${render[*]}"
old_command[ppm]="$bin/sfrender scene.sf -o render.ppm ${small[*]}"
target[png]=render.png
new_command[png]="$bin/sfrender scene.sf -o render.png ${render[*]}"
old_command[png]="$bin/sfrender scene.sf -o render.png ${small[*]}"
writers=(convert ppm png)

temporaries() { compgen -G ".$1.tmp-*" || true; }
# A wait of a few milliseconds without starting a process: a read that times
# out on a pipe nobody writes to.
exec {tick}<> <(:)

# Whether process $1 still runs: not gone and not a zombie. `kill -0` alone
# would take a zombie for a running process where SIGCHLD is blocked (as
# under ctest), since bash then reaps its children only in `wait`.
running() {
  local stat
  { read -r stat </proc/"$1"/stat; } 2>/dev/null || return 1
  stat=${stat##*) }
  [[ ${stat:0:1} != Z ]]
}

# Runs writer $1 over its old output and kills it $2 microseconds after its
# start, or, with $3 = after-temporary, $2 microseconds after its temporary
# appears (never, for -1). The temporary is watched every millisecond by
# builtins only, so that the watching hardly slows the run. Sets `opened` and
# `closed` (when the temporary was first and last seen, 0 if never), `exited`
# (when the run ended by itself, 0 if it was killed).
run_writer() {
  local w=$1 delay=$2 from=${3:-start} start now pid deadline wait_us wait_s
  cp "$w.old" "${target[$w]}"
  opened=0 closed=0 exited=0
  start=${EPOCHREALTIME/./}
  deadline=$((start + 3600000000))
  [[ $from != start ]] || ((delay < 0)) || deadline=$((start + delay))
  ${new_command[$w]} 2>/dev/null &
  pid=$!
  for (( ; ; )); do
    now=${EPOCHREALTIME/./}
    if ((now >= deadline)); then
      kill -KILL "$pid" 2>/dev/null || true
      break
    fi
    if ! running "$pid"; then
      exited=$((now - start))
      break
    fi
    if compgen -G ".${target[$w]}.tmp-*" >/dev/null; then
      if ((opened == 0)); then
        opened=$((now - start))
        [[ $from == start ]] || deadline=$((now + delay))
      fi
      closed=$((now - start))
    fi
    wait_us=$((deadline - now < 1000 ? deadline - now : 1000))
    to_seconds wait_s "$wait_us"
    read -r -t "$wait_s" -u "$tick" || true
  done
  wait "$pid" 2>/dev/null || true
}

# Each writer's run and window, from its calibration run, then corrected by
# every run that ended by itself (the calibration run, the first, is often
# the slowest): half the old figure and half the new one.
declare -A open_at close_at end_at
learn() {
  local w=$1
  ((exited > 0)) || return 0
  end_at[$w]=$(((end_at[$w] + exited) / 2))
  if ((opened > 0 && closed > opened)); then
    local window=$(((close_at[$w] - open_at[$w] + closed - opened) / 2))
    open_at[$w]=$(((open_at[$w] + opened) / 2))
    close_at[$w]=$((open_at[$w] + window))
  fi
}
for w in "${writers[@]}"; do
  # The references: the old output and the new one, each written whole.
  ${old_command[$w]} 2>/dev/null
  mv "${target[$w]}" "$w.old"
  ${new_command[$w]} 2>/dev/null
  mv "${target[$w]}" "$w.new"
  if cmp -s "$w.old" "$w.new"; then
    echo "FAIL: $w: the old and the new outputs are the same" >&2
    exit 1
  fi
  run_writer "$w" -1
  if ! cmp -s "${target[$w]}" "$w.new"; then
    echo "FAIL: $w: a second run wrote other bytes than the first" >&2
    exit 1
  fi
  if ((opened == 0)); then
    # Too short to see: the window is somewhere near the end.
    opened=$((exited * 8 / 10))
    closed=$exited
  fi
  open_at[$w]=$opened close_at[$w]=$closed end_at[$w]=$exited
  printf 'calibration: %-7s run %6.3f s, temporary seen from %6.3f s to %6.3f s\n' "$w" \
    "$(as_seconds "$exited")" "$(as_seconds "$opened")" "$(as_seconds "$closed")"
done

declare -A before during after finished
for w in "${writers[@]}"; do
  before[$w]=0 during[$w]=0 after[$w]=0 finished[$w]=0
done
failures=0
for ((i = 0; i < iterations; i++)); do
  w=${writers[i % ${#writers[@]}]}
  file=${target[$w]}
  if ((RANDOM % 10 < 6)); then
    # Inside the window, as measured: a delay after the temporary appears,
    # up to the window's length and a little more.
    delay=$(random_between 0 $((close_at[$w] - open_at[$w] + 2000)))
    run_writer "$w" "$delay" after-temporary
  else
    delay=$(random_between 0 $((end_at[$w] * 105 / 100)))
    run_writer "$w" "$delay"
  fi
  learn "$w"
  left=$(temporaries "$file")
  if cmp -s "$file" "$w.new"; then
    content=new
  elif cmp -s "$file" "$w.old"; then
    content=old
  else
    content=partial
  fi
  # Partial is the failure sought; a new target beside a temporary, or a
  # run that ended by itself without the new target, would be one too.
  if [[ $content == partial || (-n $left && $content != old) ||
    ($exited -gt 0 && $content != new) ]]; then
    echo "FAIL: kill $i ($w, after $(as_seconds "$delay") s): the target is $content" \
      "$(stat -c %s "$file") bytes, temporary: ${left:-none}" >&2
    failures=$((failures + 1))
  elif [[ -n $left ]]; then
    during[$w]=$((during[$w] + 1))
  elif ((exited > 0)); then
    finished[$w]=$((finished[$w] + 1))
  elif [[ $content == new ]]; then
    after[$w]=$((after[$w] + 1))
  else
    before[$w]=$((before[$w] + 1))
  fi
  [[ -z $left ]] || rm -f -- $left
done

echo "kills: $iterations, each target whole afterwards: $((iterations - failures))"
printf '%-8s %7s %7s %7s %9s\n' writer before during after "not killed"
total_during=0
for w in "${writers[@]}"; do
  printf '%-8s %7d %7d %7d %9d\n' "$w" "${before[$w]}" "${during[$w]}" "${after[$w]}" \
    "${finished[$w]}"
  total_during=$((total_during + during[$w]))
done
echo "(before: the old file, no temporary yet; during: killed in the write window, the" \
  "temporary left and the old file in place; after: killed after the rename, the new file)"
if ((failures > 0)); then
  echo "FAIL: $failures of $iterations kills left a partial target" >&2
  exit 1
fi
# A test that never hit the window would prove nothing.
if ((iterations >= 30 && total_during == 0)); then
  echo "FAIL: no kill landed in a write window" >&2
  exit 1
fi
echo "PASS"
rm -rf "$work"
