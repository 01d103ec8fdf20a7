#!/usr/bin/env bash
# The picture of docs/EDITORS.md: Neovim with sfls (editors/nvim) on a scene
# file with a typo, its diagnostic shown and a hover open, in xterm under
# Xvfb, taken with xwd and made a PNG with netpbm.
#
#   make_screenshot.sh BIN_DIR OUT_DIR     (cmake --build BUILD --target docs-editor-images)
#
# BIN_DIR holds sfls. Needs nvim, xterm, Xvfb (xvfb-run), xwd and netpbm.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=$(cd "${1:?usage: make_screenshot.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: make_screenshot.sh BIN_DIR OUT_DIR}
mkdir -p "$out"
out=$(cd "$out" && pwd)
for program in nvim xterm xvfb-run xwd xwdtopnm pnmtopng; do
  command -v "$program" >/dev/null || { echo "make_screenshot: $program is missing" >&2; exit 1; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/scenefile-screenshot.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp "$here/screenshot.sf" "$work/scene.sf"

# Runs inside the X server: the editor in xterm, the picture once it says
# it is ready, then the editor closed.
cat >"$work/session.sh" <<'SESSION'
set -euo pipefail
cd "$WORK"
xterm -T scenefile-screenshot -geometry 126x37+0+0 -fa 'DejaVu Sans Mono' -fs 11 \
  -bg white -fg black -e nvim --clean --cmd "set rtp+=$ROOT/editors/nvim" \
  --cmd 'set termguicolors background=light number' \
  -c "luafile $ROOT/docs/editors/screenshot.lua" scene.sf &
editor=$!
for _ in $(seq 300); do
  [[ -e $READY ]] && break
  kill -0 "$editor" 2>/dev/null || { echo "make_screenshot: the editor exited early" >&2; exit 1; }
  sleep 0.1
done
[[ -e $READY ]] || { echo "make_screenshot: the editor was not ready within 30 s" >&2; kill "$editor"; exit 1; }
xwd -silent -name scenefile-screenshot >"$WORK/shot.xwd"
kill "$editor"
wait "$editor" || true
SESSION
ROOT=$root WORK=$work READY=$work/ready SFLS=$bin/sfls \
  xvfb-run -a -s '-screen 0 1280x800x24' bash "$work/session.sh"
xwdtopnm "$work/shot.xwd" 2>/dev/null | pnmtopng -compression 9 >"$work/neovim.png"
mv "$work/neovim.png" "$out/neovim.png"
echo "make_screenshot: $out/neovim.png"
