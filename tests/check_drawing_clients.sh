#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# The drawing sheets of `exbsp drawing` read by the programs users open them in (issue: real
# clients, not our own parser): CLIENT is one of
#   ezdxf     python3-ezdxf loads the DXF, its audit finds no error and fixes nothing, and the
#             layers, linetypes, units and entities are the ones the contract names;
#   librecad  LibreCAD prints the DXF to PDF (dxf2pdf), pdftoppm rasterises it: ink on the page;
#   inkscape  Inkscape exports the SVG to PNG at the sheet's size in mm: ink on the page;
#   rsvg      librsvg (rsvg-convert) renders the SVG: 420 x 297 mm, ink on the page;
#   pdftoppm  poppler reads the PDF: one A3 landscape page, ink on it.
# A missing client skips (exit 77, shown as skipped by ctest) with a message naming the package.
# Arguments: CLIENT EXBSP_CLI MESH_DIR. The part is fandisk from the CGAL corpus (a generated
# block with a hole when the corpus is missing), drawn with a section.
set -euo pipefail
client="$1"
cli="$2"
meshes="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
skip() {
  echo "SKIPPED: $1" >&2
  exit 77
}
need() { command -v "$1" >/dev/null 2>&1 || skip "$1 is missing (apt-get install $2; scripts/setup does)"; }
python=/usr/bin/python3
part="$meshes/fandisk.off"
section="A=0,1,0,0"
if [ ! -f "$part" ]; then
  echo "check_drawing_clients: corpus missing; drawing a generated block instead" >&2
  part="$work/block.off"
  # A 60 x 40 x 20 block (8 vertices, 6 quads) is enough to exercise every layer.
  printf 'OFF\n8 6 0\n0 0 0\n60 0 0\n0 40 0\n60 40 0\n0 0 20\n60 0 20\n0 40 20\n60 40 20\n4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n' >"$part"
  section="A=0,1,0,-20"
fi
draw() {  # draw EXT [extra flags]
  local ext="$1"
  shift
  "$cli" drawing "$part" -o "sheet.$ext" --section "$section" --date 2026-01-01 -q "$@"
}
# Ink: the share of pixels of a PNG darker than mid-grey, as a number in [0, 1].
ink() {
  "$python" - "$1" <<'EOF'
import sys
from PIL import Image
im = Image.open(sys.argv[1]).convert("L")
h = im.histogram()
print(sum(h[:128]) / max(1, sum(h)))
EOF
}
expect_ink() {  # expect_ink PNG WHAT
  local share
  share="$(ink "$1")"
  "$python" -c "import sys; s=float('$share'); sys.exit(0 if 0.002 < s < 0.5 else 1)" ||
    { echo "check_drawing_clients: $2: ink share $share is not that of a line drawing" >&2; exit 1; }
  echo "check_drawing_clients: $2: ink share $share"
}
case "$client" in
  ezdxf)
    "$python" -c "import ezdxf" 2>/dev/null || skip "python3-ezdxf is missing (apt-get install python3-ezdxf; scripts/setup does)"
    draw dxf --lines-only
    "$python" - sheet.dxf <<'EOF'
import sys, collections
import ezdxf
doc = ezdxf.readfile(sys.argv[1])
audit = doc.audit()
errors = [f"{e.code} {e.message}" for e in audit.errors]
fixes = [f"{e.code} {e.message}" for e in audit.fixes]
assert not errors and not fixes, ("audit", errors[:5], fixes[:5])
assert doc.header["$INSUNITS"] == 4, doc.header["$INSUNITS"]
layers = {l.dxf.name: l for l in doc.layers}
want = {"visible": ("CONTINUOUS", 50), "hidden": ("HIDDEN", 25), "hatching": ("CONTINUOUS", 25),
        "cutting-planes": ("DASHDOT", 25), "frame": ("CONTINUOUS", 25)}
for name, (linetype, weight) in want.items():
    assert name in layers, (name, sorted(layers))
    l = layers[name]
    assert l.dxf.linetype == linetype and l.dxf.lineweight == weight, (name, l.dxf.linetype, l.dxf.lineweight)
# ISO 128-20 type 02 for the hidden width d = 0.25 mm: dash 12 d = 3, gap 3 d = 0.75.
tags = [(t.code, t.value) for t in doc.linetypes.get("HIDDEN").pattern_tags.tags]
dashes = [v for c, v in tags if c == 49]
assert dashes == [3.0, -0.75] and (40, 3.75) in tags, tags
counts = collections.Counter((e.dxftype(), e.dxf.layer) for e in doc.modelspace())
for layer in want:
    assert sum(n for (t, l), n in counts.items() if l == layer) > 0, (layer, counts)
assert counts[("TEXT", "frame")] >= 10, counts
print("check_drawing_clients: ezdxf: audit clean,", sum(counts.values()), "entities:", dict(counts))
EOF
    ;;
  librecad)
    need librecad librecad
    need pdftoppm poppler-utils
    draw dxf --lines-only
    mkdir out
    export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="$work/xdg"
    mkdir -m 700 "$work/xdg"
    timeout 300 librecad dxf2pdf -a -m -p 420x297 -t "$work/out" "$work/sheet.dxf" >/dev/null 2>&1
    [ -s out/sheet.pdf ] || { echo "check_drawing_clients: librecad wrote no PDF" >&2; exit 1; }
    pdftoppm -r 50 -png -singlefile out/sheet.pdf lc
    expect_ink lc.png "librecad dxf2pdf"
    ;;
  inkscape)
    need inkscape inkscape
    draw svg --lines-only
    timeout 300 inkscape sheet.svg --export-type=png --export-filename=ink.png --export-dpi=50 \
      --export-background=white --export-background-opacity=1 >/dev/null 2>&1
    [ -s ink.png ] || { echo "check_drawing_clients: inkscape wrote no PNG" >&2; exit 1; }
    size="$("$python" -c "from PIL import Image; print(*Image.open('ink.png').size)")"
    # 420 x 297 mm at 50 dpi: 827 x 585 pixels (Inkscape rounds).
    [ "$size" = "827 585" ] || [ "$size" = "827 584" ] || { echo "check_drawing_clients: inkscape: size $size" >&2; exit 1; }
    expect_ink ink.png "inkscape export"
    ;;
  rsvg)
    need rsvg-convert librsvg2-bin
    draw svg
    rsvg-convert -d 50 -p 50 -b white sheet.svg -o rsvg.png
    size="$("$python" -c "from PIL import Image; print(*Image.open('rsvg.png').size)")"
    [ "$size" = "827 585" ] || { echo "check_drawing_clients: rsvg: size $size (expected 827 585: A3 at 50 dpi)" >&2; exit 1; }
    expect_ink rsvg.png "rsvg-convert"
    ;;
  pdftoppm)
    need pdftoppm poppler-utils
    need pdfinfo poppler-utils
    draw pdf
    pdfinfo sheet.pdf | grep -q "Page size: *1190.55 x 841.89 pts (A3)" ||
      { echo "check_drawing_clients: pdfinfo: $(pdfinfo sheet.pdf | grep 'Page size')" >&2; exit 1; }
    pdftoppm -r 50 -png -singlefile sheet.pdf pdf
    expect_ink pdf.png "pdftoppm"
    ;;
  *)
    echo "check_drawing_clients: unknown client $client" >&2
    exit 2
    ;;
esac
