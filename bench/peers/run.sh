#!/bin/sh
# SPDX-License-Identifier: LGPL-3.0-or-later
# Times csg.js and JSCAD's BSP trees on exbsp's benchmark meshes (see README.md).
#   bench/peers/run.sh [MESH.off ...]     (default: bench/run.py's CAD and organic corpus)
# Writes bench/out/peers.jsonl (one JSON line per tool x mesh); extra options for bsp_peers.js
# can be passed in PEERS_ARGS (e.g. PEERS_ARGS="--repeat 1 --cap 60").
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
OUT="$REPO/bench/out/peers.jsonl"

if ! "$HERE/setup.sh"; then
    echo "bench/peers: skipped: node and npm are needed" >&2
    exit 0
fi

if [ $# -eq 0 ]; then
    # same names and order as CAD + ORGANIC in bench/run.py; missing files are skipped
    for m in fandisk rotor pinion anchor_dense blade turbine couplingdown ALSTOM_TEST4 b9_mesh spool \
             part joint elephant bunny00 armadillo refined_elephant; do
        f="$REPO/data/meshes/$m.off"
        if [ -f "$f" ]; then set -- "$@" "$f"; else echo "bench/peers: no $f, skipped" >&2; fi
    done
fi
if [ $# -eq 0 ]; then
    echo "bench/peers: skipped: no mesh found under $REPO/data/meshes" >&2
    exit 0
fi

mkdir -p "$(dirname "$OUT")"
trap 'rm -f "$OUT.tmp"' EXIT
echo "# $(date -u +%FT%TZ) load: $(uptime | sed 's/.*load average: //')" >&2
# shellcheck disable=SC2086
node "$HERE/bsp_peers.js" "$@" ${PEERS_ARGS:-} > "$OUT.tmp"
mv "$OUT.tmp" "$OUT"
echo "bench/peers: wrote $OUT" >&2
