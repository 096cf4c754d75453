#!/usr/bin/env bash
# Configure (Release) and build into build/: every target, or only those
# given (e.g. tribos: the program without the tests and benchmarks).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
if [ $# -gt 0 ]; then
  targets=()
  for target in "$@"; do
    targets+=(--target "$target")
  done
  cmake --build "$root/build" -j "$(nproc)" "${targets[@]}"
else
  cmake --build "$root/build" -j "$(nproc)"
fi
