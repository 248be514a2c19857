#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Writes the seed corpus of fuzz_tree (corpus/fuzz_tree/): small saved trees of every kernel
# and heuristic, made with the exbsp command line, and damaged variants of one of them.
#   tests/fuzz/make_tree_seeds.sh [EXBSP]     EXBSP: the exbsp binary (default build/src/app/exbsp)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exbsp="${1:-$here/../../build/src/app/exbsp}"
out="$here/corpus/fuzz_tree"
data="$here/../data"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
# Two crossing squares, a slanted triangle and a degenerate one: trees with splits.
cat >"$tmp/crossing.off" <<'MESH'
OFF
13 6 0
-1 -1 0
1 -1 0
1 1 0
-1 1 0
0 -1 -1
0 1 -1
0 1 1
0 -1 1
-1 0 -1
1 0.25 1
0.5 0 0.75
0 0 0
2 2 2
4 0 1 2 3
4 4 5 6 7
3 8 9 10
3 11 12 12
3 0 2 11
3 11 12 1
MESH
for kernel in exact epeck gmpq epick double; do
  for heuristic in naive min-split sampled random; do
    "$exbsp" build "$tmp/crossing.off" --kernel "$kernel" --heuristic "$heuristic" --seed 1 \
      --save "$out/seed_crossing_${kernel}_${heuristic}.exbsp" >/dev/null
  done
done
for mesh in cube.off fan.off nonmanifold.off exact_decimal.off; do
  for kernel in exact epeck double; do
    "$exbsp" build "$data/$mesh" --kernel "$kernel" --save "$out/seed_${mesh%.off}_${kernel}.exbsp" >/dev/null
  done
done
printf 'OFF\n0 0 0\n' >"$tmp/empty.off"
"$exbsp" build "$tmp/empty.off" --save "$out/seed_empty_exact.exbsp" >/dev/null
# Damaged variants (the loader must reject each one cleanly).
seed="$out/seed_crossing_exact_min-split.exbsp"
size=$(stat -c %s "$seed")
head -c $((size / 2)) "$seed" >"$out/bad_truncated.exbsp"
head -c 24 "$seed" >"$out/bad_header_only.exbsp"
cp "$seed" "$out/bad_bit_flip.exbsp"
printf '\x55' | dd of="$out/bad_bit_flip.exbsp" bs=1 seek=$((size / 3)) conv=notrunc 2>/dev/null
cp "$seed" "$out/bad_version.exbsp"
printf '\x02' | dd of="$out/bad_version.exbsp" bs=1 seek=8 conv=notrunc 2>/dev/null
{ cat "$seed"; printf 'garbage'; } >"$out/bad_trailing.exbsp"
ls "$out" | wc -l
