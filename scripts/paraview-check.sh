#!/usr/bin/env bash
# Opens three runs in ParaView the way a user does (docs/reading-output.md): short runs of the
# cylinder, the stocking and the female top, each run's view.py under pvpython on a virtual
# display, a screenshot of each, and scripts/paraview-check.py's checks of what ParaView read
# (field names and ranges against the run's pressure.csv, the colour bar's unit, the load steps
# as time, a screenshot that is not blank).
#
# Usage: scripts/paraview-check.sh [--install] [--keep-runs] [--tightfit PROGRAM] [--out DIR]
#                                  [CASE...]
#   --install  first install ParaView and Xvfb (Debian 12: apt-get install paraview xvfb
#              xauth) and, where pvpython is missing, unpack python3-paraview into
#              ~/.cache/tightfit/paraview (TIGHTFIT_PARAVIEW_HOME; see below why not install it)
#   --keep-runs  open the runs already in DIR instead of running them again
#   PROGRAM    the tightfit executable (default build/app/tightfit)
#   DIR        where the runs and the screenshots go (default output/paraview-check):
#              DIR/CASE/ the run, DIR/CASE.png its screenshot
#   CASE       cylinder, stocking, top (default all three)
# About two minutes of CPU: each run is cut short (below), each view about 5 s.
# Exit status: 0 all checks pass, 1 a check failed, 2 bad usage or a run failed, 77 no pvpython
# or no xvfb-run (nothing checked; CTest reports the test as skipped).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tightfit=$root/build/app/tightfit
out=$root/output/paraview-check
install=0
keep_runs=0
cases=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --install) install=1 ;;
    --keep-runs) keep_runs=1 ;;
    --tightfit) tightfit=$(realpath "$2"); shift ;;
    --out) out=$(realpath -m "$2"); shift ;;
    cylinder | stocking | top) cases+=("$1") ;;
    *) echo "paraview-check: unknown argument '$1' (see the usage at the top of $0)" >&2; exit 2 ;;
  esac
  shift
done
[[ ${#cases[@]} -gt 0 ]] || cases=(cylinder stocking top)

# Debian 12's python3-paraview (pvpython) conflicts with python3-vtk9, which libvtk9-dev, and so
# tightfit's build, needs: it is unpacked into a folder of its own instead of installed, and its
# modules are put first on pvpython's path (TIGHTFIT_PARAVIEW_PYTHON, read by paraview-check.py).
private=${TIGHTFIT_PARAVIEW_HOME:-${XDG_CACHE_HOME:-$HOME/.cache}/tightfit/paraview}
if [[ $install == 1 ]]; then
  sudo=""
  [[ $(id -u) == 0 ]] || sudo=sudo
  $sudo apt-get install -y --no-install-recommends paraview xvfb xauth
  if ! command -v pvpython >/dev/null; then
    mkdir -p "$private"
    (cd "$private" && rm -f python3-paraview_*.deb && apt-get download python3-paraview &&
      dpkg -x python3-paraview_*.deb root && rm python3-paraview_*.deb)
  fi
fi
pvpython=$(command -v pvpython || true)
if [[ -z $pvpython && -x $private/root/usr/bin/pvpython3.11 ]]; then
  pvpython=$private/root/usr/bin/pvpython3.11
  export TIGHTFIT_PARAVIEW_PYTHON=$private/root/usr/lib/python3/dist-packages
fi
if [[ -z $pvpython ]]; then
  echo "paraview-check: skipped, pvpython not found (install it with: $0 --install)"
  exit 77
fi
if ! command -v xvfb-run >/dev/null; then
  echo "paraview-check: skipped, xvfb-run not found (install it with: $0 --install)"
  exit 77
fi
if [[ ! -x $tightfit ]]; then
  echo "paraview-check: $tightfit is not an executable (build it: scripts/build.sh)" >&2
  exit 2
fi

# The cases cut short: the cylinder at half resolution over three load steps; the stocking and
# the top settled to a looser stop rule (a relative residual of 1e-3, two contact multiplier
# updates, 10 um of penetration; the top on a 25 mm mesh): pictures, not measurements.
loose="Solver/Relative tolerance=1e-3|Mass spring/Contact multiplier updates=2|Solver/Gap tolerance=1e-5"
settings_for() {
  case $1 in
    cylinder) echo "cylinder_T.prm|Garment/Mesh scale=2|Protocol/Final alpha=1.2|Protocol/Alpha increment=0.1" ;;
    stocking) echo "stocking_female.prm|$loose" ;;
    top) echo "top_female.prm|Garment/Pattern file/Mesh edge length=0.025|$loose" ;;
  esac
}
unit_for() { [[ $1 == stocking ]] && echo mmHg || echo Pa; }

mkdir -p "$out"
cd "$root"
status=0
for name in "${cases[@]}"; do
  IFS='|' read -r -a parts <<<"$(settings_for "$name")"
  args=(run "cases/${parts[0]}" --output "$out/$name")
  for s in "${parts[@]:1}"; do args+=(--set "$s"); done
  echo "== $name: tightfit ${args[*]}"
  start=$SECONDS
  if [[ $keep_runs == 1 && -s $out/$name/pressure.csv && -s $out/$name/view.py ]]; then
    echo "   (kept the run in $out/$name)"
  elif ! { rm -rf "${out:?}/$name" && "$tightfit" "${args[@]}" >"$out/$name.log" 2>&1; }; then
    echo "paraview-check: the $name run failed; its output: $out/$name.log" >&2
    tail -n 5 "$out/$name.log" >&2
    exit 2
  fi
  echo "   run: $((SECONDS - start)) s; ParaView:"
  start=$SECONDS
  # pvpython 5.11 on Xvfb now and then fails to open the display as it starts ("bad X server
  # connection", SIGABRT; about one start in six on a loaded machine, with or without MPI):
  # up to five tries.
  for try in 1 2 3 4 5; do
    set +e
    xvfb-run -a -n $((100 + RANDOM % 800)) -s "-screen 0 1280x800x24 -nolisten tcp" \
      "$pvpython" --no-mpi scripts/paraview-check.py "$out/$name" "$out/$name.png" \
      "$(unit_for "$name")" >"$out/$name.paraview.log" 2>&1
    result=$?
    set -e
    grep -q "bad X server connection" "$out/$name.paraview.log" || break
    echo "   (pvpython could not open the virtual display, try $try of 5)"
  done
  grep -e "^  ok" -e "^  FAIL" "$out/$name.paraview.log" || true
  if [[ $result != 0 ]]; then
    status=1
    grep -q "^  FAIL" "$out/$name.paraview.log" ||
      echo "paraview-check: pvpython stopped (status $result); its output: $out/$name.paraview.log"
  fi
  echo "   ParaView: $((SECONDS - start)) s, screenshot $out/$name.png"
done
[[ $status == 0 ]] && echo "paraview-check: every check passed" || echo "paraview-check: a check failed"
exit $status
