# Shell helpers the benchmark scripts share; sourced, not run.

# value KEY FILE: the value of a "key: value" line.
value() { sed -n "s/^$1: //p" "$2" | head -n 1; }
# median of the numbers given as arguments (mean of the middle two if even).
median() {
  printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 }
    END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
maximum() { printf '%s\n' "$@" | sort -g | tail -n 1; }
minimum() { printf '%s\n' "$@" | sort -g | head -n 1; }
# fmt DIGITS NUMBER: fixed-point with DIGITS decimals.
fmt() { awk -v v="$2" "BEGIN { printf \"%.$1f\", v }" </dev/null; }
# thousands 1234567 -> 1,234,567
thousands() { printf '%s' "$1" | sed -e ':a' -e 's/\B[0-9]\{3\}\>/,&/' -e 'ta'; }

# From /usr/bin/time -v: the wall time in seconds ("h:mm:ss" or "m:ss.ss")
# with DIGITS decimals (2 unless given), the CPU time, and the peak resident
# set size in MB (10^6 bytes).
time_wall() {
  sed -n 's/.*Elapsed (wall clock) time.*): //p' "$1" |
    awk -F: -v digits="${2:-2}" '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i
      printf "%." digits "f", s }'
}
time_cpu() {
  awk -F': ' '/User time \(seconds\)|System time \(seconds\)/ { s += $2 } END { printf "%.2f", s }' "$1"
}
time_peak_mb() {
  sed -n 's/.*Maximum resident set size (kbytes): //p' "$1" | awk '{ printf "%.1f", $1 * 1024 / 1e6 }'
}
# The seconds of one of POV-Ray's "... Time: 0 hours 0 minutes 2 seconds (2.457 seconds)".
pov_seconds() { sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$2" | head -n 1; }

# Sets build_type from BUILD's CMake cache, for the reports, and warns when
# it is not a Release build: its timings would mislead.
warn_unless_release() {
  build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$1/CMakeCache.txt" 2>/dev/null || true)
  [[ $build_type == Release ]] || log "warning: $1 is a '${build_type:-unknown}' build, not Release"
}

# What the reports say of the machine and the build: the CPU's model, the
# memory, the compiler of BUILD's CMake cache, POV-Ray's version and the
# commit of ROOT (each "unknown" or empty when it cannot be told).
cpu_model() { sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1; }
memory_total() { awk '/^MemTotal:/ { printf "%.1f GB", $2 * 1024 / 1e9 }' /proc/meminfo 2>/dev/null || true; }
compiler_of() {
  local compiler
  compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$1/CMakeCache.txt" 2>/dev/null || true)
  "${compiler:-c++}" --version 2>/dev/null | head -n 1 || true
}
povray_version() { povray --version 2>&1 | sed -n 's/^\(POV-Ray [0-9.]*[^ ]*\).*/\1/p' | head -n 1; }
short_commit() { git -C "$1" rev-parse --short HEAD 2>/dev/null || echo unknown; }

# replace_section NAME FILE: FILE's text in place of the lines between NAME's
# markers ("<!-- BEGIN NAME", "<!-- END NAME") in $doc, or at its end when it
# has none yet. Uses $doc and the scratch folder $work of the sourcing script.
replace_section() {
  if grep -q "^<!-- BEGIN $1" "$doc"; then
    awk -v section="$2" -v name="$1" '
      $0 ~ "^<!-- BEGIN " name { while ((getline line < section) > 0) print line; skip = 1; next }
      $0 ~ "^<!-- END " name { skip = 0; next }
      !skip { print }' "$doc" >"$work/doc.md"
    cat "$work/doc.md" >"$doc"
  else
    { echo; cat "$2"; } >>"$doc"
  fi
}
