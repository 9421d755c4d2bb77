"""Renders a tubeform result with ParaView, headless (run by scripts/paraview
under pvbatch): the mesh read through the .xmf, warped by `displacement_u`,
coloured by a cell field, with the tool's nodal contact forces
(`contact_force`) as arrows, at one time of the load path.

    pvbatch scripts/paraview_render.py RESULT.xmf OUT.png [LAMBDA] [FIELD]

LAMBDA: the load parameter of the step to show (default 1: the end of
loading; the nearest written step is taken). FIELD: a cell field (default
eps_p; von_mises, sigma_xx, ...).
"""
import sys

from paraview.simple import (XDMFReader, WarpByVector, Glyph, CreateView, Show, ColorBy, GetColorTransferFunction,
                             SaveScreenshot, GetScalarBar)

xmf, png = sys.argv[1], sys.argv[2]
lam = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
field = sys.argv[4] if len(sys.argv) > 4 else "eps_p"
reader = XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
t = min(times, key=lambda v: abs(v - lam))
warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "displacement_u"]
view = CreateView("RenderView")
view.ViewSize = [900, 800]
view.ViewTime = t
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
shown = Show(warp, view)
ColorBy(shown, ("CELLS", field))
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction(field), view)
bar.Title, bar.ComponentTitle = field, ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
shown.RescaleTransferFunctionToDataRange(False, True)
names = [a.Name for a in reader.PointData]
if "contact_force" in names:
    arrows = Glyph(Input=warp, GlyphType="Arrow")
    arrows.OrientationArray = ["POINTS", "contact_force"]
    arrows.ScaleArray = ["POINTS", "contact_force"]
    arrows.ScaleFactor = 0.04  # mm of arrow per N/mm of force: 2-3 mm for the default tube's contact forces
    arrows.GlyphMode = "All Points"
    glyphs = Show(arrows, view)
    ColorBy(glyphs, None)
    glyphs.AmbientColor = glyphs.DiffuseColor = [0.1, 0.3, 0.9]
view.ResetCamera()
SaveScreenshot(png, view, ImageResolution=[900, 800])
print(f"paraview_render: {png} (lambda {t:g}, {field}{', contact forces' if 'contact_force' in names else ''})")
