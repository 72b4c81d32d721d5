#!/usr/bin/env bash
# The main job: installs what is missing, builds the executable (only: scripts/test.sh builds
# the tests and benchmarks), and runs the paper's cylinder study on both of its garments ("T"
# and "4 5T"). Results go to output/cylinder_T and output/cylinder_45T.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh tightfit
./build/app/tightfit run cases/cylinder_T.prm cases/cylinder_45T.prm "$@"
