#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds and tests with.
# Does nothing when every package is already present; needs root otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libcli11-dev libglm-dev libtinygltf-dev nlohmann-json3-dev
  libopenimageio-dev liblcms2-dev libgtest-dev libgmock-dev
  # sfrender writes PNG, the common case, with libpng itself (png_file.h).
  libpng-dev
  # The colour-managed images' test converts sfrender's PNG, TIFF and EXR
  # with oiiotool.
  openimageio-tools
  # POV-Ray renders the cross-checks; the tutorial-style scenes include its
  # colors.inc.
  povray povray-includes
  # make docs (and its test) builds the API reference with Doxygen; the man
  # pages are made from each tool's --help by help2man, and their test shows
  # them with man; the bash completions' test loads them with bash-completion.
  doxygen help2man man-db bash-completion
  # make bench draws the plots of docs/PERFORMANCE.md with gnuplot.
  gnuplot-nox
  # Optional, for the benchmarks only: bench/embree_trace traces sfrender's
  # primary rays with Embree 3 ("Against Embree" in docs/PERFORMANCE.md);
  # without it CMake leaves that target out and the rest builds as before.
  libembree-dev
  # glTF tests: Blender exports and imports glTF (its glTF add-on needs numpy).
  blender python3-numpy
  # Other programs that read the exports, in their tests: assimp (OBJ and glTF
  # without lights) and f3d (glTF, in a bench of its materials).
  assimp-utils f3d
  # The Python module (python/): pybind11 and Python's headers to build it,
  # pytest to test it; Blender runs the same Debian Python 3.11 that imports
  # it, and its add-on (blender/io_scene_sf) is tested there.
  pybind11-dev python3-pybind11 python3-dev python3-pytest
  # The render test reads sfrender's float EXR with OpenImageIO's Python
  # module, to compare it with the module's numbers exactly; the typing test
  # holds the package's annotations and stubs to mypy --strict.
  python3-openimageio mypy
  # sfbuild: GLFW and epoxy for OpenGL 3.3; its X11 test runs it in Xvfb on
  # Mesa's software OpenGL, types with xdotool and takes screenshots with xwd
  # and netpbm.
  libglfw3-dev libepoxy-dev libgl1-mesa-dri xvfb xauth xdotool x11-apps netpbm
  # sfbuild's panels (key list, scene, properties, status line): Dear ImGui
  # 1.86, whose libimgui.a carries the GLFW and OpenGL 3 backends.
  libimgui-dev
  # The hostile-input tests measure sfcheck's peak memory with GNU time.
  time
  # The VS Code extension's test lists its .vsix with unzip.
  unzip
  # The Slurm test (tests/slurm) starts a single-node cluster of its own
  # (munged, slurmctld, slurmd) to run scripts/slurm/ on.
  slurm-wlm munge
  # make test-valgrind runs the tools' end-to-end tests under valgrind;
  # bench/tracers.sh counts instructions with its callgrind.
  valgrind
  # make fuzz builds the libFuzzer targets with clang and its runtime.
  clang libclang-rt-14-dev
  # The renderer's GPU path (renderer/gpu/, sfrender --device gpu): the
  # Vulkan loader and headers, glslangValidator to compile its compute
  # shader to SPIR-V at build time (glslc beside it), and Mesa's lavapipe,
  # a CPU Vulkan driver with shaderFloat64, on which its tests run on every
  # machine; vulkaninfo shows what a machine offers.
  libvulkan-dev glslang-tools glslc mesa-vulkan-drivers vulkan-tools
  # The language server's editor test runs Neovim headless against sfls;
  # docs/EDITORS.md's picture (make docs) shows Neovim in xterm under Xvfb.
  neovim xterm
  # make web compiles the library and the renderer to WebAssembly with
  # Debian's Emscripten (em++, with its own clang, binaryen and libc++).
  emscripten
  # The page's tests (tests/web) and make bench's load times run it in a real
  # browser: Debian's Chromium, driven by playwright-core, which downloads
  # no browser of its own.
  chromium
)
# The glTF Validator and the VS Code extension's build (tsc, vsce) run on
# Node.js; a machine with node and npm already (from Debian or elsewhere)
# keeps them.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

# The npm trees, each pinned by its package-lock.json (and an .npmrc that
# runs no install scripts): `npm ci` in FOLDER when one of the PATHS under
# its node_modules is missing.
npm_ci_unless_present() {
  local folder="$1"
  shift
  local root
  root="$(cd "$(dirname "$0")/.." && pwd)"
  for path in "$@"; do
    if [ ! -e "$root/$folder/node_modules/$path" ]; then
      echo "install-deps: npm ci in $folder" >&2
      (cd "$root/$folder" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
      return
    fi
  done
}

install_npm_packages() {
  # The glTF Validator and glTF-Transform.
  npm_ci_unless_present tests/gltf gltf-validator @gltf-transform/functions
  # The VS Code extension's compiler, packager and grammar tests.
  npm_ci_unless_present editors/vscode .bin/vsce .bin/tsc .bin/vscode-tmgrammar-snap \
    vscode-languageclient
  # The page's tests: playwright-core (which downloads no browser) and pngjs.
  npm_ci_unless_present tests/web playwright-core pngjs
  # The page's editor, three.js, esbuild (its binary is the npm package
  # @esbuild/linux-x64) and coi-serviceworker.
  npm_ci_unless_present web .bin/esbuild three @codemirror/view coi-serviceworker
}

if [ ${#missing[@]} -eq 0 ]; then
  install_npm_packages
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=sudo
  else
    echo "install-deps: need root to install: ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_npm_packages
