#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Builds the exbsp libFuzzer targets and runs each for RUNS executions (README.md). Its
# setup lines (here, defaults from the environment) have the form of make_tree_seeds.sh's.
#
#   tests/fuzz/run.sh [RUNS]          RUNS defaults to 1000000; 0 = only build and replay
#
# Per target: replays tests/fuzz/crashes/<target>/* (the kept findings), then fuzzes with
# the seed corpus tests/fuzz/corpus/<target>/ (read only) and the working corpus
# build/corpus/<target>/ (new inputs go there, kept between runs), dictionary
# dict/<format>.dict, -timeout=2 s, ASan + UBSan. A crash, timeout, leak or out-of-memory
# stops that target; its input is copied to tests/fuzz/crashes/<target>/ and the script
# exits with status 1 after the summary. Logs: build/logs/<target>.log.
#
# Environment:
#   FUZZ_TARGETS      targets to run (default: "fuzz_off fuzz_obj fuzz_ply fuzz_stl fuzz_scene fuzz_number fuzz_tree")
#   FUZZ_MAX_LEN      largest input in bytes (default 16384)
#   FUZZ_TIMEOUT      seconds per input before libFuzzer reports a timeout (default 2)
#   FUZZ_JOBS         parallel compile jobs (default 2)
#   FUZZ_SEED         libFuzzer's random seed (default: a new one each run; CI fixes it, so
#                     that a run repeats the same mutations on the same code)
#   EXBSP_FUZZ_ALLOW  known findings fuzz_scene lets pass (see fuzz_scene.cpp, README.md)
#   CXX               the clang++ to use (default clang++)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
runs="${1:-1000000}"
targets="${FUZZ_TARGETS:-fuzz_off fuzz_obj fuzz_ply fuzz_stl fuzz_scene fuzz_number fuzz_tree}"
max_len="${FUZZ_MAX_LEN:-16384}"
timeout="${FUZZ_TIMEOUT:-2}"
jobs="${FUZZ_JOBS:-2}"
seed="${FUZZ_SEED:-0}"  # libFuzzer: -seed=0 means "pick one"
build="$here/build"

if ! [[ "$seed" =~ ^[0-9]+$ ]]; then
  echo "$0: FUZZ_SEED must be a non-negative integer, got '$seed'" >&2
  exit 2
fi
if ! [[ "$runs" =~ ^[0-9]+$ ]]; then
  echo "usage: $0 [RUNS]   (RUNS: a non-negative integer, default 1000000)" >&2
  exit 2
fi

# ---- build ----
mkdir -p "$build"
cmake -S "$here" -B "$build/cmake" -G Ninja -DCMAKE_CXX_COMPILER="${CXX:-clang++}" >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 2; }
# shellcheck disable=SC2086
cmake --build "$build/cmake" -j"$jobs" --target $targets

mkdir -p "$build/logs" "$build/tmp"
export TMPDIR="$build/tmp"  # fuzz_scene's fixture directory lives here
summary=()
status=0

for target in $targets; do
  binary="$build/cmake/$target"
  format="${target#fuzz_}"
  seeds="$here/corpus/$target"
  work="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  kept="$here/crashes/$target"
  log="$build/logs/$target.log"
  mkdir -p "$work" "$artifacts"

  # Replay the kept findings: each must now pass (or be listed in EXBSP_FUZZ_ALLOW).
  replay="no kept findings"
  if compgen -G "$kept/*" >/dev/null; then
    failing=0
    total=0
    for input in "$kept"/*; do
      total=$((total + 1))
      if ! "$binary" -runs=1 "$input" >"$build/logs/$target.replay.log" 2>&1; then
        failing=$((failing + 1))
        echo "$target: kept finding still fails: ${input#"$here"/}" >&2
        grep -m1 -E "exbsp fuzz:|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error" \
          "$build/logs/$target.replay.log" >&2 || true
      fi
    done
    replay="kept findings: $((total - failing))/$total pass"
    ((failing == 0)) || status=1
  fi

  if ((runs == 0)); then
    summary+=("$target: built; $replay")
    continue
  fi

  marker="$build/logs/$target.start"
  touch "$marker"
  start=$(date +%s)
  set +e
  "$binary" "$work" "$seeds" -runs="$runs" -seed="$seed" -max_len="$max_len" -timeout="$timeout" \
    -rss_limit_mb=2048 -dict="$here/dict/$format.dict" -artifact_prefix="$artifacts/" \
    -report_slow_units=1 -print_final_stats=1 >"$log" 2>&1
  rc=$?
  set -e
  seconds=$(($(date +%s) - start))

  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<<"$last")
  slowest=$(sed -n 's/^Slowest unit: \([0-9]*\) s.*/\1/p' "$log" | sort -n | tail -1)
  slow_note="slowest unit < 1 s"
  [ -z "$slowest" ] || slow_note="slowest unit ${slowest} s"

  # New artifacts. A slow-unit-* (an input that once took >= 1 s) is timed again: on this
  # shared machine a busy moment can make a fast input look slow. It is a finding only when
  # it still takes more than 1 s per execution; timeouts (> FUZZ_TIMEOUT) always are.
  found=0
  while IFS= read -r artifact; do
    name=$(basename "$artifact")
    if [[ "$name" == slow-unit-* ]]; then
      t0=$(date +%s%N)
      "$binary" -runs=5 "$artifact" >/dev/null 2>&1 || true
      ms=$((($(date +%s%N) - t0) / 5000000))
      if ((ms <= 1000)); then
        slow_note="$slow_note, re-run ${ms} ms: not reproduced"
        continue
      fi
      slow_note="$slow_note, re-run ${ms} ms"
    fi
    found=$((found + 1))
    mkdir -p "$kept"
    cp "$artifact" "$kept/"
    echo "$target: finding kept as ${kept#"$here"/}/$name" >&2
  done < <(find "$artifacts" -type f -newer "$marker")
  if ((rc != 0 || found > 0)); then
    status=1
    grep -m3 -E "exbsp fuzz:|ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error|SUMMARY" "$log" >&2 || true
  fi
  summary+=("$(printf '%-12s %9s execs in %5s s (%6s exec/s), cov %5s edges, ft %6s, corpus %5s, peak rss %4s MB, %s, findings %d (exit %d); %s' \
    "$target:" "${execs:-?}" "$seconds" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "${rss:-?}" \
    "$slow_note" "$found" "$rc" "$replay")")
done

echo
echo "== exbsp fuzz summary (runs=$runs, seed=$seed, max_len=$max_len, timeout=${timeout}s${EXBSP_FUZZ_ALLOW:+, EXBSP_FUZZ_ALLOW=$EXBSP_FUZZ_ALLOW}) =="
printf '%s\n' "${summary[@]}"
exit "$status"
