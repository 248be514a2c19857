#!/usr/bin/env bash
# Installs the built exbsp into a temporary prefix and builds and runs examples/consumer
# against it with find_package(exbsp). Arguments: BUILD_DIR SOURCE_DIR.
set -euo pipefail
build_dir="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/examples/consumer" -B "$work/build" -G Ninja \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/exbsp_consumer"
echo "install_consumer: OK"
