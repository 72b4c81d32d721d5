#!/usr/bin/env bash
# Installs what tightfit needs from Debian 12's packages, skipping what is already installed.
# Safe to run any number of times. `--fuzz` adds clang and its libFuzzer and sanitizer runtimes
# for scripts/fuzz.sh (not needed to build, test or run tightfit).
#
# BLAS: OpenBLAS's single-threaded build (libopenblas0-serial) is installed by default; Debian
# then points libblas.so.3 and liblapack.so.3 at it system-wide (its alternatives outrank the
# reference BLAS). CHOLMOD's and MUMPS's dense kernels run three times faster with it on fine
# meshes (a load step of the 96600-vertex tube: 38 s against 125 s of one core,
# docs/performance.md, Scaling), and being the serial build it keeps every process on one core.
# `--reference-blas` opts out: OpenBLAS is not installed, and where it is, the alternatives are
# set back to the reference BLAS. The test suite passes with either. (`--fast-blas`, the old
# opt-in, is accepted and does nothing more than the default.)
set -euo pipefail

packages=(
  cmake make g++                 # build tools
  libdeal.ii-dev openmpi-bin     # deal.II 9.4 with PETSc, MPI and p4est; mpirun
  libeigen3-dev libvtk9-dev      # small dense algebra; VTU output, mesh readers, rendering
  libsuitesparse-dev             # CHOLMOD: the mass-spring backend's implicit integrator
  libcgal-dev                    # AABB trees, 2D constrained Delaunay meshing
  libpugixml-dev nlohmann-json3-dev libdxflib-dev  # SVG, JSON and DXF pattern files
  libgtest-dev libbenchmark-dev  # tests and benchmarks
  gnuplot-nox                    # the charts of scripts/plots/ (not tightfit itself)
)
reference_blas=false
for option in "$@"; do
  case $option in
    --fuzz) packages+=(clang-14 libclang-rt-14-dev) ;;  # libFuzzer, ASan and UBSan runtimes
    --reference-blas) reference_blas=true ;;
    --fast-blas) ;;  # the default
    *)
      echo "install-dependencies.sh: unknown option '$option' (--fuzz, --reference-blas)" >&2
      exit 2
      ;;
  esac
done
$reference_blas || packages+=(libopenblas0-serial)  # optimised BLAS and LAPACK, one thread

as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)

# Points libblas.so.3 and liblapack.so.3 back at the reference implementation (both stay
# installed; `update-alternatives --auto` undoes it).
use_reference_blas() {
  local arch library
  arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
  for library in blas lapack; do
    if [ -e "/usr/lib/$arch/$library/lib$library.so.3" ]; then
      "${as_root[@]}" update-alternatives --set "lib$library.so.3-$arch" \
        "/usr/lib/$arch/$library/lib$library.so.3" >/dev/null
    fi
  done
  echo "tightfit: libblas.so.3 and liblapack.so.3 point at the reference BLAS and LAPACK"
}

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "tightfit: every dependency is installed"
else
  echo "tightfit: installing ${missing[*]}"
  echo "tightfit: on a fresh Debian 12 that is about 780 packages (800 MB): a minute or more"
  "${as_root[@]}" apt-get update -qq
  # dpkg's unsafe-io skips the sync after each unpacked file: on a fresh machine it halves the
  # installation (docs/performance.md, "Building"); a crash during it would need the
  # installation run again, as any interrupted one does.
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends \
    -o Dpkg::Options::=--force-unsafe-io "${missing[@]}"
fi
if $reference_blas && dpkg-query -W -f='${Status}' libopenblas0-serial 2>/dev/null |
  grep -q "install ok installed"; then
  use_reference_blas
fi
