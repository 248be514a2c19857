# SPDX-License-Identifier: LGPL-3.0-or-later
# Sourced by the scenes/make_*_images.sh scripts: the exbsp binary to run ($1 of the script,
# else $EXBSP, else build/src/app/exbsp), the output folder scenes/images/ and a temporary
# folder removed on exit. Sets: here, exbsp, out, tmp. $1 of `images_setup` names the script.
images_setup() {
  local script="$1"
  shift
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  exbsp="${1:-${EXBSP:-$here/../build/src/app/exbsp}}"
  if [ ! -x "$exbsp" ]; then
    echo "$script: no exbsp binary at $exbsp (build it, or pass its path)" >&2
    exit 2
  fi
  out="$here/images"
  mkdir -p "$out"
  tmp="$(mktemp -d)"
  trap 'rm -rf "$tmp"' EXIT
}
