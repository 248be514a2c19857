#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Every source file of exbsp (C++, CMake, Python, shell, JavaScript) names its licence with an
# `SPDX-License-Identifier:` line as its first line (after a shebang), and the identifier is
# consistent with the CGAL headers the file includes directly: a file that includes a CGAL
# header whose own SPDX line is GPL-3.0-or-later (CGAL's GPL packages: Triangulation_2,
# Convex_hull_3, Surface_mesh, ...) must be GPL-3.0-or-later itself (docs/licence.md).
# Transitive inclusion of a GPL package by the LGPL libraries is caught by the compiler
# instead (CGAL_LICENSE_ERROR, src/CMakeLists.txt).
# Arguments: SOURCE_DIR [CGAL_INCLUDE_DIR (default /usr/include)]. Run by ctest (spdx_headers).
set -euo pipefail
source_dir="$1"
cgal_include="${2:-/usr/include}"
cd "$source_dir"
patterns=('*.cpp' '*.h' '*.hpp' '*.in' '*.cmake' 'CMakeLists.txt' '*.py' '*.sh' '*.js' '*.mjs' 'scripts/*' '.ci/*')
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- "${patterns[@]}")
else  # a source tarball: the same patterns over the tree
  mapfile -t files < <(find . -path ./build -prune -o -path ./data -prune -o -type f \
    \( -name '*.cpp' -o -name '*.h' -o -name '*.hpp' -o -name '*.in' -o -name '*.cmake' \
       -o -name CMakeLists.txt -o -name '*.py' -o -name '*.sh' -o -name '*.js' -o -name '*.mjs' \
       -o -path './scripts/*' -o -path './.ci/*' \) -print | sed 's|^\./||' | grep -v '/node_modules/')
fi
for f in LICENSE LICENSES/LGPL-3.0-or-later.txt LICENSES/GPL-3.0-or-later.txt; do
  [ -s "$f" ] || { echo "check_spdx: $f is missing" >&2; exit 1; }
done
bad=0
declare -A gpl_header=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  line="$(head -1 "$f")"
  if [[ "$line" == '#!'* ]]; then line="$(sed -n 2p "$f")"; fi
  if [[ ! "$line" =~ ^(//|#)\ SPDX-License-Identifier:\ (LGPL-3\.0-or-later|GPL-3\.0-or-later)$ ]]; then
    echo "check_spdx: $f: first line is not '// SPDX-License-Identifier: LGPL-3.0-or-later' (or '#', or GPL-3.0-or-later)" >&2
    bad=1
    continue
  fi
  id="${BASH_REMATCH[2]}"
  [ "$id" = GPL-3.0-or-later ] && continue
  # An LGPL file must not include a GPL CGAL header.
  while read -r header; do
    if [ -z "${gpl_header[$header]+x}" ]; then
      spdx="$(grep -m1 -h 'SPDX-License-Identifier' "$cgal_include/$header" 2>/dev/null || true)"
      if [[ "$spdx" == *GPL-3.0-or-later* && "$spdx" != *LGPL-3.0-or-later* ]]; then
        gpl_header[$header]=1
      else
        gpl_header[$header]=0
      fi
    fi
    if [ "${gpl_header[$header]}" = 1 ]; then
      echo "check_spdx: $f includes <$header>, a GPL-3.0-or-later CGAL package: the file must be GPL-3.0-or-later" >&2
      bad=1
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*<\(CGAL\/[^>]*\)>.*/\1/p' "$f")
done
[ "$bad" = 0 ] || exit 1
echo "check_spdx: ${#files[@]} source files carry an SPDX-License-Identifier line"
