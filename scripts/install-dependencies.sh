#!/usr/bin/env bash
# Installs what tightfit needs from Debian 12's packages, skipping what is already installed.
# Safe to run any number of times. `--fuzz` adds clang and its libFuzzer and sanitizer runtimes
# for scripts/fuzz.sh (not needed to build, test or run tightfit). `--fast-blas` adds OpenBLAS
# (single-threaded), which Debian then uses for libblas.so.3 system-wide: CHOLMOD's and MUMPS's
# dense kernels, two to three times faster on fine meshes (docs/performance.md, Scaling); the
# test suite passes with either BLAS.
set -euo pipefail

packages=(
  cmake make g++                 # build tools
  libdeal.ii-dev openmpi-bin     # deal.II 9.4 with PETSc, MPI and p4est; mpirun
  libeigen3-dev libvtk9-dev      # small dense algebra; VTU output, mesh readers, rendering
  libsuitesparse-dev             # CHOLMOD: the mass-spring backend's implicit integrator
  libcgal-dev                    # AABB trees, 2D constrained Delaunay meshing
  libpugixml-dev nlohmann-json3-dev libdxflib-dev  # SVG, JSON and DXF pattern files
  libgtest-dev libbenchmark-dev  # tests and benchmarks
  gnuplot-nox                    # plots
)
for option in "$@"; do
  case $option in
    --fuzz) packages+=(clang-14 libclang-rt-14-dev) ;;  # libFuzzer, ASan and UBSan runtimes
    --fast-blas) packages+=(libopenblas0-serial) ;;     # optimised BLAS, one thread
    *) echo "install-dependencies.sh: unknown option '$option' (--fuzz, --fast-blas)" >&2; exit 2 ;;
  esac
done

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "tightfit: every dependency is installed"
  exit 0
fi

echo "tightfit: installing ${missing[*]}"
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
"${as_root[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends \
  "${missing[@]}"
