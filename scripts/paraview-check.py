# Runs a tightfit run's view script (view.py, docs/reading-output.md) under pvpython, saves its
# screenshot, and checks what ParaView read against the run's own tables:
#   - the garment series: its times are pressure.csv's alpha column, and at each time the
#     largest pressure_Pa is that step's p_max_Pa (pressure.csv keeps 10 significant digits:
#     relative 1e-9), the smallest is not negative;
#   - the body series carries pressure_Pa, pressure_mmHg and under_garment, its pressure_mmHg
#     is its pressure_Pa over 133.322387415 Pa/mmHg, and its largest pressure at most the
#     garment's (the body's is interpolated from the garment's);
#   - the colour map runs from 0 to the largest p_max_Pa of the run, in the unit on the bar;
#   - the animation's times are the load steps' alpha;
#   - the angular profile (when the run has one) holds pressure.csv's rows of pressure_theta.csv;
#   - the screenshot is not blank: over 5% of its pixels differ from the white background, in
#     at least 64 different colours.
# Usage: pvpython scripts/paraview-check.py RUN_DIR SCREENSHOT.png UNIT
#   UNIT: the unit the colour bar should state (Pa or mmHg).
# Prints one line per check; exits 1 when one fails.
import csv
import os
import sys

# ParaView's Python modules unpacked beside the system's VTK (scripts/paraview-check.sh) come
# first, before the system's own vtkmodules.
if os.environ.get('TIGHTFIT_PARAVIEW_PYTHON'):
    sys.path.insert(0, os.environ['TIGHTFIT_PARAVIEW_PYTHON'])

from paraview.simple import *
from paraview import servermanager
from vtkmodules.vtkIOImage import vtkPNGReader

PA_PER_MMHG = 133.322387415
run_dir, screenshot, unit = sys.argv[1], sys.argv[2], sys.argv[3]
failures = []


def check(ok, what):
    print(('  ok    ' if ok else '  FAIL  ') + what)
    if not ok:
        failures.append(what)


def close(a, b, relative):
    return abs(a - b) <= relative * max(abs(a), abs(b), 1e-300)


def table(name):
    with open(os.path.join(run_dir, name)) as f:
        return list(csv.DictReader(f))


def point_arrays(source, t):
    source.UpdatePipeline(t)
    info = source.GetPointDataInformation()
    return {info.GetArray(i).GetName(): info.GetArray(i).GetRange(0)
            for i in range(info.GetNumberOfArrays())}


# The view script as ParaView's shell runs it, but without starting an interaction.
view_script = os.path.join(run_dir, 'view.py')
code = compile(open(view_script).read(), view_script, 'exec')
view_globals = {'__name__': 'tightfit_view', '__file__': view_script}
exec(code, view_globals)
time_steps = view_globals['time_steps']  # the view's own reading of a series' times
view = GetActiveView()
SaveScreenshot(screenshot, GetLayout(view), ImageResolution=[1280, 720],
               FontScaling='Do not scale fonts')

rows = table('pressure.csv')
alphas = [float(r['alpha']) for r in rows]
p_max = [float(r['p_max_Pa']) for r in rows]
garment, body = FindSource('garment'), FindSource('body')
times = time_steps(garment)
check(len(times) == len(alphas) and all(close(t, a, 1e-9) for t, a in zip(times, alphas)),
      'garment.pvd times %s are the alphas of pressure.csv %s' % (times, alphas))
for t, top in zip(times, p_max):
    arrays = point_arrays(garment, t)
    low, high = arrays.get('pressure_Pa', (float('nan'), float('nan')))
    check(close(high, top, 1e-9) and low >= 0,
          'garment at alpha %g: pressure_Pa %g to %g Pa, p_max_Pa %g' % (t, low, high, top))
    names = sorted(arrays)
    check(all(n in arrays for n in ('contact', 'normal_force_N', 'vertex_area_m2')),
          'garment at alpha %g: point arrays %s' % (t, ' '.join(names)))
    body_arrays = point_arrays(body, t)
    has = all(n in body_arrays for n in ('pressure_Pa', 'pressure_mmHg', 'under_garment'))
    check(has, 'body at alpha %g: point arrays %s' % (t, ' '.join(sorted(body_arrays))))
    if has:
        body_Pa, body_mmHg = body_arrays['pressure_Pa'][1], body_arrays['pressure_mmHg'][1]
        check(close(body_mmHg * PA_PER_MMHG, body_Pa, 1e-12) and body_Pa <= high * (1 + 1e-12),
              'body at alpha %g: largest pressure %g Pa = %g mmHg, at most the garment\'s'
              % (t, body_Pa, body_mmHg))

array = 'pressure_mmHg' if unit == 'mmHg' else 'pressure_Pa'
lut = GetColorTransferFunction(array)
expected_top = max(p_max) / (PA_PER_MMHG if unit == 'mmHg' else 1.0)
points = lut.RGBPoints
check(close(points[0], 0.0, 0) and close(points[-4], expected_top, 1e-9),
      'colour map %s from %g to %g, the run\'s largest p_max_Pa in %s %g'
      % (array, points[0], points[-4], unit, expected_top))
bar = GetScalarBar(lut, view)
check(bar.Visibility == 1 and bar.Title == 'pressure (%s)' % unit,
      'colour bar "%s" shown' % bar.Title)
scene_times = list(GetTimeKeeper().TimestepValues) if len(alphas) > 1 else alphas
check(len(scene_times) == len(alphas) and all(close(t, a, 1e-9)
                                              for t, a in zip(scene_times, alphas)),
      'the time control steps through the alphas %s' % scene_times)

profile = FindSource('angular profile')
if os.path.exists(os.path.join(run_dir, 'pressure_theta.csv')):
    sectors = table('pressure_theta.csv')
    check(profile is not None, 'the angular profile is shown')
    if profile is not None:
        rows_read = servermanager.Fetch(profile)  # the vtkTable ParaView's CSV reader made
        pressure = rows_read.GetColumnByName('pressure_Pa')
        largest = max(float(r['pressure_Pa']) for r in sectors if r['pressure_Pa'])
        read_largest = pressure.GetRange(0)[1] if pressure is not None else float('nan')
        check(rows_read.GetColumnByName('theta_deg') is not None and
              rows_read.GetNumberOfRows() == len(sectors) and close(read_largest, largest, 1e-9),
              'angular profile: %d rows, largest pressure_Pa %g (csv: %d rows, %g)'
              % (rows_read.GetNumberOfRows(), read_largest, len(sectors), largest))

reader = vtkPNGReader()
reader.SetFileName(screenshot)
reader.Update()
image = reader.GetOutput()
scalars = image.GetPointData().GetScalars()
n, components = scalars.GetNumberOfTuples(), scalars.GetNumberOfComponents()
colours, not_white = set(), 0
for i in range(n):
    rgb = tuple(int(scalars.GetComponent(i, c)) for c in range(3))
    colours.add(rgb)
    not_white += rgb != (255, 255, 255)
check(not_white > 0.05 * n and len(colours) >= 64,
      'screenshot %s: %.1f%% of %d pixels drawn, %d colours'
      % (screenshot, 100.0 * not_white / n, n, len(colours)))
# ParaView 5.11's pvpython may crash while it tears down: the status is this script's.
sys.stdout.flush()
os._exit(1 if failures else 0)
