#!/usr/bin/env bash
# Command 2 of the README: install what is missing, build, run every test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/install_dependencies.sh"
bash "$root/tools/build.sh"
cd "$root/build"
# In parallel on every core; the tests that start MPI runs take two cores
# each and one at a time (tests/CMakeLists.txt).
ctest --output-on-failure -j "$(nproc)" "$@"
