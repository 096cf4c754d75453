#!/usr/bin/env bash
# Command 1 of the README: install what is missing, build, run the default
# scene. Output goes to output/cylinder_elastic_3d/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/tools/install_dependencies.sh"
bash "$root/tools/build.sh" tribos
cd "$root"
./build/tribos parameters/cylinder_elastic_3d.prm
