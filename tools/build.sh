#!/usr/bin/env bash
# Configure (Release) and build into build/: every target, or only those
# given (e.g. tribos: the program without the tests and benchmarks).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# Ninja for a new build folder: with make, a source file added or removed
# rebuilds the precompiled headers and with them every object (19 min);
# with Ninja only the new file. An existing folder keeps its generator.
generator=()
if [ ! -f "$root/build/CMakeCache.txt" ]; then
  generator=(-G Ninja)
fi
cmake -S "$root" -B "$root/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  > /dev/null
if [ $# -gt 0 ]; then
  targets=()
  for target in "$@"; do
    targets+=(--target "$target")
  done
  cmake --build "$root/build" -j "$(nproc)" "${targets[@]}"
else
  cmake --build "$root/build" -j "$(nproc)"
fi
