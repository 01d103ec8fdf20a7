#!/usr/bin/env bash
# The package as its users get it (ctest: package.install-and-use, label
# "package"):
#
#   bash scripts/check-package.sh BUILD_DIR
#
# 1. installs the build (already built: `cmake --install`, nothing is
#    rebuilt) to a temporary prefix, and checks its layout, the docs and
#    the man pages' references to them and the editor packages included;
# 2. builds examples/count-objects out of tree against that prefix alone:
#    with find_package (CMAKE_PREFIX_PATH), shared and static, and with
#    pkg-config (PKG_CONFIG_PATH), shared and --static;
# 3. runs each on a scene file, a glTF file and a POV-Ray file ("N objects,
#    M lights", exit 0) and on an invalid file (FILE:LINE:COLUMN: lines,
#    exit 1), and once with no file (exit 2); builds examples/render-to-png
#    with find_package and libpng, whose PNG of a scene must decode to the
#    pixels of sfrender's, and which prints an invalid file's diagnostics
#    with the source quoted (exit 1) and a missing file as exit 3;
# 4. where the build has the Python module: imports the installed package
#    with the build's python (Debian's /usr/bin/python3) from the prefix's
#    Python folder (PYTHONPATH) and reads and renders a scene; installs the
#    Blender add-on's zip into a fresh Blender user folder and, with no
#    PYTHONPATH, imports a scene through it (the module found where the
#    install's _site.py says);
# 5. moves the prefix elsewhere and renders a PNG with the moved sfrender
#    (its OpenImageIO module found relative to the program), then a lone
#    copy of sfrender, which cannot find the module, must say so; the moved
#    Python package still imports, and the moved add-on folder finds it.
# Everything happens under a temporary folder, removed at the end.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:?usage: check-package.sh BUILD_DIR}
build=$(cd "$build" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/scenefile-package.XXXXXX")
work=$(cd "$work" && pwd -P)
trap 'rm -rf "$work"' EXIT

failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}
step() { echo "== $*"; }

# The compiler of the build, and its launcher (ccache) if any, so that the
# example is built the same way.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt" | head -n 1; }
cxx=$(cache_value CMAKE_CXX_COMPILER)
launcher=$(cache_value CMAKE_CXX_COMPILER_LAUNCHER)
# lib, or lib/x86_64-linux-gnu for a build configured for /usr.
libdir=$(cache_value CMAKE_INSTALL_LIBDIR)
libdir=${libdir:-lib}
cmake_args=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=$cxx"
            "-DCMAKE_CXX_FLAGS=-Wall -Wextra -Werror")
[[ -n $launcher ]] && cmake_args+=("-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher")

# --- 1. Install ---------------------------------------------------------------
prefix=$work/prefix
step "cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" ||
  { cat "$work/install.log" >&2; exit 1; }
soname_file=$prefix/$libdir/libscenefile.so.0
for file in include/scenefile/read.h include/scenefile/formats.def \
            include/scenefile/object_kinds.def include/scenefile/options/gltf.h \
            "$libdir"/libscenefile.a "$libdir"/libscenefile.so \
            "$libdir"/libscenefile.so.0 "$libdir"/libscenefile.so.0.1.0 \
            "$libdir"/cmake/scenefile/scenefileConfig.cmake \
            "$libdir"/cmake/scenefile/scenefileConfigVersion.cmake \
            "$libdir"/cmake/scenefile/scenefileTargets.cmake \
            "$libdir"/cmake/scenefile/scenefileStaticTargets.cmake "$libdir"/pkgconfig/scenefile.pc \
            "$libdir"/scenefile/sfrender_oiio.so bin/sfcheck bin/sfconvert bin/sfrender bin/sfls \
            share/man/man1/sfcheck.1 share/man/man1/sfconvert.1 share/man/man1/sfrender.1 share/man/man1/sfls.1 \
            share/bash-completion/completions/sfcheck share/bash-completion/completions/sfconvert \
            share/bash-completion/completions/sfrender share/bash-completion/completions/sfls; do
  [[ -e $prefix/$file ]] || fail "the install has no $file"
done
if [[ -e $soname_file ]]; then
  soname=$(objdump -p "$soname_file" | sed -n 's/^ *SONAME *//p')
  [[ $soname == libscenefile.so.0 ]] || fail "libscenefile.so's SONAME is '$soname', not libscenefile.so.0"
fi
[[ ! -e $prefix/bin/sfrender_oiio.so ]] || fail "sfrender_oiio.so is installed in bin/"
# The docs, with the guide's pictures and scenes, and none of the files that
# make them; each man page's SEE ALSO names installed docs, at the prefix
# the build was configured for (the man pages are made at build time).
docdir=$(cache_value CMAKE_INSTALL_DOCDIR)
docdir=${docdir:-share/doc/scenefile}
for file in GUIDE.md TOOLS.md DIAGNOSTICS.md images/guide/row-reflectivity.png \
            guide/first-scene.txt; do
  [[ -e $prefix/$docdir/$file ]] || fail "the install has no $docdir/$file"
done
compgen -G "$prefix/$docdir/perf/*.png" >/dev/null || fail "the install has no $docdir/perf/*.png"
for file in CMakeLists.txt man guide/make_images.sh; do
  [[ ! -e $prefix/$docdir/$file ]] || fail "the install has $docdir/$file"
done
configured=$(cache_value CMAKE_INSTALL_PREFIX)/$docdir
for page in "$prefix"/share/man/man1/*.1; do
  named=$(grep -o "$configured/[A-Za-z_./]*\.md" "$page" | sort -u)
  [[ -n $named ]] || fail "$(basename "$page") names no doc in $configured"
  for doc in $named; do
    [[ -e $prefix/$docdir/${doc#"$configured"/} ]] ||
      fail "$(basename "$page") names $doc, which the install lacks"
  done
done

# The editor packages: Neovim's set-up, and the VS Code extension wherever
# the build made it (it needs node and editors/vscode/node_modules).
datadir=$(cache_value CMAKE_INSTALL_DATADIR)
editors=${datadir:-share}/scenefile/editors
for file in nvim/README.md nvim/ftdetect/scenefile.vim nvim/lua/scenefile/init.lua; do
  [[ -e $prefix/$editors/$file ]] || fail "the install has no $editors/$file"
done
vsix=scenefile-$(cache_value CMAKE_PROJECT_VERSION).vsix
if [[ -e $build/editors/$vsix ]]; then
  cmp -s "$build/editors/$vsix" "$prefix/$editors/$vsix" ||
    fail "the install has no $editors/$vsix as the build made it"
fi

# --- 2. and 3. Build the example each way, and run it ---------------------------
valid_sf=$root/testdata/valid/all-primitives.sf
gltf=$root/testdata/gltf/torus-and-sphere.gltf
pov=$root/testdata/pov/valid/losses.pov
invalid=$root/testdata/invalid/blank-line-inside-record.sf

# check_program NAME PROGRAM: the four files and a usage error.
check_program() {
  local name=$1 program=$2 file status out err
  for file in "$valid_sf" "$gltf" "$pov"; do
    status=0
    out=$("$program" "$file" 2>"$work/err") || status=$?
    if [[ $status -ne 0 || ! $out =~ ^[0-9]+\ objects,\ [0-9]+\ lights$ ]]; then
      fail "$name $(basename "$file"): exit $status, printed '$out'; $(cat "$work/err")"
    else
      echo "$name $(basename "$file"): $out"
    fi
  done
  status=0
  out=$("$program" "$invalid" 2>"$work/err") || status=$?
  err=$(cat "$work/err")
  if [[ $status -ne 1 || -n $out ]] ||
     ! grep -qE "^$invalid:[0-9]+:[0-9]+: error: " "$work/err"; then
    fail "$name on an invalid file: exit $status (not 1), stdout '$out', stderr '$err'"
  else
    echo "$name $(basename "$invalid"): exit 1, $(head -n 1 "$work/err" | sed "s|^$root/||")"
  fi
  status=0
  "$program" >/dev/null 2>&1 || status=$?
  [[ $status -eq 2 ]] || fail "$name with no file: exit $status, not 2"
}

example=$root/examples/count-objects
for kind in shared static; do
  step "find_package(scenefile), $kind"
  flag=OFF
  [[ $kind == static ]] && flag=ON
  if cmake -S "$example" -B "$work/cmake-$kind" "${cmake_args[@]}" \
       "-DCMAKE_PREFIX_PATH=$prefix" -DCOUNT_OBJECTS_STATIC=$flag >"$work/cmake-$kind.log" 2>&1 &&
     cmake --build "$work/cmake-$kind" >>"$work/cmake-$kind.log" 2>&1; then
    check_program "cmake-$kind" "$work/cmake-$kind/count-objects"
  else
    fail "building count-objects with find_package ($kind)"
    cat "$work/cmake-$kind.log" >&2
  fi
done
# The shared build names libscenefile.so.0; the static one does not.
if [[ -x $work/cmake-shared/count-objects ]]; then
  objdump -p "$work/cmake-shared/count-objects" | grep -q 'NEEDED *libscenefile\.so\.0$' ||
    fail "count-objects (shared) does not need libscenefile.so.0"
fi
if [[ -x $work/cmake-static/count-objects ]]; then
  ! objdump -p "$work/cmake-static/count-objects" | grep -q 'NEEDED *libscenefile' ||
    fail "count-objects (static) needs libscenefile.so"
fi

export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
compile=(${launcher:+"$launcher"} "$cxx" -std=c++20 -O2 -Wall -Wextra -Werror)
step "pkg-config scenefile: $(pkg-config --cflags --libs scenefile)"
# shellcheck disable=SC2046
if "${compile[@]}" "$example/count_objects.cpp" -o "$work/pc-shared" \
     $(pkg-config --cflags --libs scenefile) "-Wl,-rpath,$(pkg-config --variable=libdir scenefile)" \
     2>"$work/pc-shared.log"; then
  check_program pkg-config "$work/pc-shared"
else
  fail "building count-objects with pkg-config"
  cat "$work/pc-shared.log" >&2
fi
# --static: the static library alone (a folder where -lscenefile finds only
# libscenefile.a) needs nothing that the --static line leaves out.
step "pkg-config --static scenefile: $(pkg-config --static --libs scenefile)"
mkdir -p "$work/static-only"
ln -s "$prefix/$libdir/libscenefile.a" "$work/static-only/libscenefile.a"
# shellcheck disable=SC2046
if "${compile[@]}" "$example/count_objects.cpp" -o "$work/pc-static" -L"$work/static-only" \
     $(pkg-config --cflags --static --libs scenefile) 2>"$work/pc-static.log"; then
  check_program "pkg-config --static" "$work/pc-static"
  ! objdump -p "$work/pc-static" | grep -q 'NEEDED *libscenefile' ||
    fail "count-objects (pkg-config --static) needs libscenefile.so"
else
  fail "building count-objects with pkg-config --static"
  cat "$work/pc-static.log" >&2
fi

# render-to-png: reading by path, the diagnostics' text form and a render
# through the installed package; its PNG decodes to sfrender's pixels.
example=$root/examples/render-to-png
sphere=$root/examples/red-sphere.sf
step "render-to-png, find_package(scenefile) and libpng"
if cmake -S "$example" -B "$work/render-to-png" "${cmake_args[@]}" "-DCMAKE_PREFIX_PATH=$prefix" \
     >"$work/render-to-png.log" 2>&1 &&
   cmake --build "$work/render-to-png" >>"$work/render-to-png.log" 2>&1; then
  program=$work/render-to-png/render-to-png
  status=0
  "$program" "$sphere" "$work/example.png" 64 48 2>"$work/example.err" || status=$?
  "$prefix/bin/sfrender" "$sphere" -o "$work/sfrender.png" --width 64 --height 48 --quiet ||
    fail "sfrender could not render $sphere"
  if [[ $status -ne 0 ]]; then
    fail "render-to-png: exit $status, $(cat "$work/example.err")"
  elif [[ $(pngtopnm "$work/example.png" | sed -n 2p) != "64 48" ]]; then
    fail "render-to-png wrote no 64x48 PNG"
  elif ! cmp -s <(pngtopnm "$work/example.png") <(pngtopnm "$work/sfrender.png"); then
    fail "render-to-png's pixels are not sfrender's"
  else
    echo "render-to-png: a 64x48 PNG, the pixels of sfrender's; $(tr '\r' '\n' <"$work/example.err" | tail -n 1)"
  fi
  status=0
  "$program" "$invalid" "$work/invalid.png" 2>"$work/invalid.err" || status=$?
  if [[ $status -ne 1 || -e $work/invalid.png ]] || ! grep -q ' | ' "$work/invalid.err" ||
     ! grep -qE "^$invalid:[0-9]+:[0-9]+: error: .* \[[a-z-]+\]$" "$work/invalid.err"; then
    fail "render-to-png on an invalid file: exit $status, $(cat "$work/invalid.err")"
  fi
  status=0
  "$program" "$work/no-such.sf" "$work/none.png" 2>"$work/missing.err" || status=$?
  [[ $status -eq 3 ]] || fail "render-to-png on a missing file: exit $status, not 3"
else
  fail "building render-to-png with find_package"
  cat "$work/render-to-png.log" >&2
fi
nm -DC "$prefix/$libdir/libscenefile.so" >"$work/symbols"
grep -q ' T scene::renderScene(' "$work/symbols" || fail "libscenefile.so has no scene::renderScene"

# --- 4. The Python module and the Blender add-on ------------------------------
python=$(cache_value SCENEFILE_PYTHON_EXECUTABLE)
pydir=$(cache_value SCENEFILE_PYTHON_INSTALL_DIR)
# One call of the installed package: read a scene, render a few pixels.
check_python() {
  local where=$1 out status=0
  out=$(cd "$work" && PYTHONPATH=$where "$python" -c "
import scenefile
assert scenefile.__file__.startswith('$where/'), scenefile.__file__
scene = scenefile.read('$valid_sf')
image = scenefile.render(scene, width=8, height=6)
print(f'{len(scene.objects)} objects, an image of {image.shape}, from {scenefile.__file__}')
" 2>&1) || status=$?
  if [[ $status -ne 0 ]]; then
    fail "the Python package in $where: exit $status, $out"
  else
    echo "python3: $out"
  fi
}
# The add-on, loaded as Blender loads one, imports a scene; PYTHONPATH unset,
# so that only the add-on's own way to the module counts.
check_addon() {
  local label=$1 script=$2 status=0 out
  out=$(cd "$work" && env -u PYTHONPATH BLENDER_USER_SCRIPTS="$work/blender-user-$label" \
        blender -b --factory-startup --python-exit-code 1 --python "$script" -- \
        "$valid_sf" 2>&1) || status=$?
  if [[ $status -ne 0 ]] || ! grep -q '^ADDON: ' <<<"$out"; then
    fail "the Blender add-on ($label): exit $status, $(tail -n 5 <<<"$out")"
  else
    echo "blender ($label): $(grep '^ADDON: ' <<<"$out" | sed 's/^ADDON: //')"
  fi
}
addon_import='
import bpy, numpy, sys
numpy.bool = bool  # Debian 12: Blender 3.4 and numpy 1.24 (see tests/gltf)
args = sys.argv[sys.argv.index("--") + 1:]
assert bpy.ops.import_scene.sf(filepath=args[0]) == {"FINISHED"}
import scenefile
meshes = [o for o in bpy.data.objects if o.type == "MESH"]
print(f"ADDON: imported {len(meshes)} objects with scenefile from {scenefile.__file__}")
'
if [[ -n $python && -n $pydir ]]; then
  step "the Python package in $prefix/$pydir, and the Blender add-on"
  for file in "$pydir/scenefile/__init__.py" "$pydir/scenefile/_checks.py" \
              "$pydir/scenefile/_model.py" \
              "$pydir/scenefile/_core.pyi" "$pydir/scenefile/py.typed" \
              share/scenefile/io_scene_sf.zip share/scenefile/blender/addons/io_scene_sf/__init__.py \
              share/scenefile/blender/addons/io_scene_sf/_site.py; do
    [[ -e $prefix/$file ]] || fail "the install has no $file"
  done
  compgen -G "$prefix/$pydir/scenefile/_core.*.so" >/dev/null || fail "the install has no _core module"
  check_python "$prefix/$pydir"
  if command -v blender >/dev/null 2>&1; then
    # Factory settings first: they would disable the add-on enabled after.
    printf '%s\n' 'import addon_utils, bpy' 'bpy.ops.wm.read_factory_settings(use_empty=True)' \
      "bpy.ops.preferences.addon_install(filepath=\"$prefix/share/scenefile/io_scene_sf.zip\")" \
      'addon_utils.enable("io_scene_sf", default_set=True, handle_error=None)' \
      "$addon_import" >"$work/zip.py"
    check_addon zip "$work/zip.py"
  else
    echo "blender is not installed: the add-on is not tried"
  fi
fi

# --- 5. A moved prefix --------------------------------------------------------
moved=$work/elsewhere/moved-prefix
mkdir -p "$(dirname "$moved")"
mv "$prefix" "$moved"
step "the prefix moved to $moved: sfrender -o render.png"
status=0
(cd "$work" && "$moved/bin/sfrender" "$root/examples/red-sphere.sf" -o "$work/render.png" \
   --width 32 --height 24 --quiet) 2>"$work/render.err" || status=$?
if [[ $status -ne 0 ]]; then
  fail "the moved sfrender exited $status: $(cat "$work/render.err")"
elif [[ ! -s $work/render.png || $(head -c 8 "$work/render.png" | od -An -tx1 | tr -d ' \n') != 89504e470d0a1a0a ]]; then
  fail "the moved sfrender wrote no PNG"
else
  echo "render.png: a PNG of $(stat -c %s "$work/render.png") bytes"
fi
# The moved library still serves its programs.
if [[ -x $work/cmake-shared/count-objects ]]; then
  status=0
  LD_LIBRARY_PATH=$moved/$libdir "$work/cmake-shared/count-objects" "$valid_sf" >/dev/null || status=$?
  [[ $status -eq 0 ]] || fail "count-objects with the moved libscenefile.so: exit $status"
fi
# A lone copy of sfrender finds no module and says so; .ppm and .png, which
# it writes itself, still work.
mkdir -p "$work/lone"
cp "$moved/bin/sfrender" "$work/lone/sfrender"
status=0
"$work/lone/sfrender" --width 8 --height 8 -o "$work/lone.tif" 2>"$work/lone.err" || status=$?
if [[ $status -ne 2 ]] || ! grep -q "could not be loaded from $work/$libdir/scenefile/sfrender_oiio.so" "$work/lone.err" ||
   ! grep -q '\.ppm and \.png need no module' "$work/lone.err"; then
  fail "a lone sfrender asked for a TIFF: exit $status, $(cat "$work/lone.err")"
else
  echo "a lone sfrender: $(cat "$work/lone.err")"
fi
for image in lone.ppm lone.png; do
  "$work/lone/sfrender" --width 8 --height 8 --quiet -o "$work/$image" ||
    fail "a lone sfrender cannot write $image"
done
# The Python package needs nothing from where it was installed, and the
# add-on's folder finds it relative to itself.
if [[ -n $python && -n $pydir ]]; then
  check_python "$moved/$pydir"
  if command -v blender >/dev/null 2>&1; then
    printf '%s\n' 'import bpy, sys' 'bpy.ops.wm.read_factory_settings(use_empty=True)' \
      "sys.path.insert(0, \"$moved/share/scenefile/blender/addons\")" \
      'import io_scene_sf' 'io_scene_sf.register()' "$addon_import" >"$work/moved.py"
    check_addon moved "$work/moved.py"
  fi
fi

if ((failures > 0)); then
  echo "FAIL: $failures checks of the installed package" >&2
  exit 1
fi
echo "PASS: the installed package builds and runs count-objects four ways and render-to-png, a moved prefix renders a PNG${python:+, and the Python package and the Blender add-on work from it}"
