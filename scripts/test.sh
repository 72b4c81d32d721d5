#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (GoogleTest under CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
# OpenMPI refuses to start as root without these; the MPI tests run mpirun.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
