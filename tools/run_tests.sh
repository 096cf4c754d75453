#!/usr/bin/env bash
# Command 2 of the README: install what is missing, build, run every test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/install_dependencies.sh"
bash "$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure "$@"
