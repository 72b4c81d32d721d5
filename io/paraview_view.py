# The view, built from SETTINGS above; the same in every run (tightfit's io/paraview_view.py,
# which io/paraview_view_script.cc writes after the run's SETTINGS).

import csv
import os
import sys

from paraview.simple import *


def run_folder():
    """The folder of this script: beside it lie the run's files."""
    if '__file__' in globals():
        return os.path.dirname(os.path.abspath(__file__))
    return SETTINGS['written_to']


def time_steps(source):
    """The source's times (a list, maybe empty)."""
    times = source.TimestepValues
    if times is None:
        return []
    try:
        return [float(t) for t in times]
    except TypeError:
        return [float(times)]


def largest(source, array, times):
    """The largest value of a point array at the given times (0 if absent)."""
    top = 0.0
    for t in times or [None]:
        if t is None:
            source.UpdatePipeline()
        else:
            source.UpdatePipeline(t)
        info = source.GetPointDataInformation().GetArray(array)
        if info is not None:
            top = max(top, info.GetRange(0)[1])
    return top


def show_run():
    folder = run_folder()
    array = 'pressure_mmHg' if SETTINGS['in_mmHg'] else 'pressure_Pa'
    unit = 'mmHg' if SETTINGS['in_mmHg'] else 'Pa'
    view = GetActiveViewOrCreate('RenderView')
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass

    garment = PVDReader(registrationName='garment',
                        FileName=os.path.join(folder, SETTINGS['garment']))
    body = PVDReader(registrationName='body', FileName=os.path.join(folder, SETTINGS['body']))
    garment_shown = garment
    if SETTINGS['in_mmHg']:
        # The garment's files hold Pa; the body's hold both.
        garment_shown = Calculator(registrationName='garment (mmHg)', Input=garment)
        garment_shown.ResultArrayName = 'pressure_mmHg'
        garment_shown.Function = 'pressure_Pa/%.12g' % SETTINGS['pascal_per_mmHg']
    body_shown = body
    if SETTINGS['body_has_pressure']:
        # Where no garment lies the body's pressure is NaN, drawn grey (the colour map's NaN
        # colour): apart from where the garment lies and does not press (0, the map's bottom).
        body_shown = PythonCalculator(registrationName='body (no garment: NaN)', Input=body)
        body_shown.ArrayAssociation = 'Point Data'
        body_shown.ArrayName = array
        body_shown.Expression = 'numpy.where(under_garment > 0, %s, numpy.nan)' % array
    coloured = [garment_shown] + ([body_shown] if SETTINGS['body_has_pressure'] else [])

    body_display = Show(body_shown, view)
    if SETTINGS['body_has_pressure']:
        ColorBy(body_display, ('POINTS', array))
    else:
        body_display.ColorArrayName = ['POINTS', '']
        body_display.DiffuseColor = [0.78, 0.78, 0.78]
        body_display.AmbientColor = [0.78, 0.78, 0.78]
    garment_display = Show(garment_shown, view)
    ColorBy(garment_display, ('POINTS', array))

    # One colour map for both, from zero to the largest pressure of any load step (set after
    # the displays, which would otherwise fit it to the first step's).
    times = time_steps(garment)
    top = max([largest(s, array, times) for s in coloured] + [0.0]) or 1.0
    lut = GetColorTransferFunction(array)
    lut.ApplyPreset('Viridis (matplotlib)', True)
    lut.AutomaticRescaleRangeMode = 'Never'
    lut.RescaleTransferFunction(0.0, top)
    lut.NanColor = [0.78, 0.78, 0.78]
    GetOpacityTransferFunction(array).RescaleTransferFunction(0.0, top)

    # The garment's edge (its boundary: hem, openings), so that where it ends shows.
    surface = ExtractSurface(registrationName='garment surface', Input=garment)
    edge = FeatureEdges(registrationName='garment edge', Input=surface)
    edge.BoundaryEdges = 1
    edge.FeatureEdges = 0
    edge.NonManifoldEdges = 0
    edge.ManifoldEdges = 0
    edge_display = Show(edge, view)
    edge_display.ColorArrayName = ['POINTS', '']
    edge_display.DiffuseColor = [0.0, 0.0, 0.0]
    edge_display.AmbientColor = [0.0, 0.0, 0.0]
    edge_display.LineWidth = 2.0
    Hide(surface, view)

    bar = GetScalarBar(lut, view)
    bar.Title = 'pressure (%s)' % unit
    bar.ComponentTitle = ''
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 14
    bar.LabelFontSize = 12
    bar.RangeLabelFormat = '%.3g'
    bar.Visibility = 1

    title = Text(registrationName='title')
    title.Text = SETTINGS['title']
    title_display = Show(title, view)
    title_display.WindowLocation = 'Upper Left Corner'
    title_display.Color = [0.0, 0.0, 0.0]
    title_display.FontSize = 14

    # The load steps are the series' time: the .pvd times are the steps' alpha.
    step = PythonAnnotation(registrationName='load step', Input=garment)
    step.ArrayAssociation = 'Field Data'
    step.Expression = "'load step %d of %d (pressure.csv step %d), alpha = %.4g' % (t_index + 1, len(t_steps), t_index, t_value)"
    step_display = Show(step, view)
    step_display.WindowLocation = 'Upper Right Corner'
    step_display.Color = [0.0, 0.0, 0.0]
    step_display.FontSize = 14

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    if times:
        scene.AnimationTime = times[-1]

    # From the front: looking along the view direction, up shown upwards, everything in frame.
    d, up = SETTINGS['view_direction'], SETTINGS['view_up']
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = [-d[0], -d[1], -d[2]]
    view.CameraViewUp = list(up)
    view.CameraParallelProjection = 1
    view.ResetCamera(False)
    SetActiveSource(garment)

    if SETTINGS['angular_profile']:
        show_angular_profile(view, os.path.join(folder, SETTINGS['angular_profile']))
    Render(view)
    return view


def show_angular_profile(view, path):
    """pressure_theta.csv as a chart beside the view: tightfit's pressure per sector (the sectors
    that hold a vertex) and the closed form."""
    profile = CSVReader(registrationName='angular profile', FileName=[path])
    # An empty sector's pressure cell is empty, which the reader makes 0: the chart shows a
    # copy of the column without them (NaN: not drawn).
    sectors = PythonCalculator(registrationName='sectors with vertices', Input=profile)
    sectors.ArrayAssociation = 'Row Data'
    sectors.ArrayName = 'tightfit'
    sectors.Expression = 'numpy.where(n_vertices > 0, pressure_Pa, numpy.nan)'
    layout = GetLayout(view)
    chart = CreateView('XYChartView')
    layout.SplitHorizontal(0, 0.6)
    layout.AssignView(2, chart)
    line = Show(sectors, chart, 'XYChartRepresentation')
    line.AttributeType = 'Row Data'
    line.UseIndexForXAxis = 0
    line.XArrayName = 'theta_deg'
    line.SeriesVisibility = ['tightfit', 'p_theory_Pa']
    line.SeriesLabel = ['tightfit', 'tightfit', 'p_theory_Pa', 'closed form']
    line.SeriesColor = ['tightfit', '0.267', '0.005', '0.329', 'p_theory_Pa', '0.8', '0.4', '0.0']
    line.SeriesMarkerStyle = ['tightfit', '4']
    chart.ChartTitle = 'pressure round the cylinder'
    chart.ChartTitleFontSize = 14
    chart.BottomAxisTitle = 'angle (degrees)'
    chart.LeftAxisTitle = 'pressure (Pa)'
    for axis in ('Bottom', 'Left'):
        setattr(chart, axis + 'AxisTitleFontSize', 12)
        setattr(chart, axis + 'AxisLabelFontSize', 11)
    chart.LegendFontSize = 11
    with open(path) as table:
        rows = [row for row in csv.DictReader(table)]
    largest_Pa = max([float(r[c]) for r in rows for c in ('pressure_Pa', 'p_theory_Pa') if r[c]]
                     + [0.0])
    chart.LeftAxisUseCustomRange = 1
    chart.LeftAxisRangeMinimum = 0.0
    chart.LeftAxisRangeMaximum = 1.2 * largest_Pa or 1.0
    chart.BottomAxisUseCustomRange = 1
    chart.BottomAxisRangeMinimum = 0.0
    chart.BottomAxisRangeMaximum = 360.0
    SetActiveView(view)


def started_as_script():
    """pvpython view.py: the script's path is argv[0]; ParaView's GUI (--script, or the Python
    shell's Run Script) leaves argv[0] empty, and its window is already there."""
    args = getattr(sys, 'argv', None) or ['']
    return bool(args[0]) and args[0] != '-c'


def option(name):
    args = getattr(sys, 'argv', [])
    return args[args.index(name) + 1] if name in args[:-1] else None


VIEW = show_run()
if __name__ == '__main__' and started_as_script():
    screenshot = option('--screenshot')
    if screenshot:
        SaveScreenshot(screenshot, GetLayout(VIEW), ImageResolution=[1280, 720],
                       FontScaling='Do not scale fonts')
    else:
        Interact(VIEW)
