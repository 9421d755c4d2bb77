"""Renders a tubeform result with ParaView, headless (run by scripts/paraview
under pvbatch): the mesh read through the .xmf, warped by `displacement_u`,
coloured by a cell field, with the tool's nodal contact forces
(`contact_force`) as arrows and the tools' outlines, at one time of the load path.

    pvbatch scripts/paraview_render.py RESULT.xmf OUT.png [LAMBDA] [FIELD]

LAMBDA: the load parameter of the step to show (default 1: the end of
loading; the nearest written step is taken). FIELD: a cell field (default
eps_p; von_mises, sigma_xx, ...).
"""
import sys

import h5py

from paraview import servermanager
from paraview.simple import (XDMFReader, WarpByVector, Glyph, CreateView, Show, ColorBy, GetColorTransferFunction,
                             SaveScreenshot, GetScalarBar, ExtractBlock)

xmf, png = sys.argv[1], sys.argv[2]
lam = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
field = sys.argv[4] if len(sys.argv) > 4 else "eps_p"
reader = XDMFReader(FileNames=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
# The .xmf's times are the load path's seconds (a tool scene's stroke at 1 mm/s); the step of LAMBDA is found
# through the result file's /time, which holds each field step's load parameter.
with h5py.File(xmf[:-4] + ".h5", "r") as h:
    lams = list(h["/time"][:, 0])
t = times[min(range(len(lams)), key=lambda k: abs(lams[k] - lam))]
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
warp.UpdatePipeline(t)
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
    glyphs.ColorArrayName = ["POINTS", ""]  # a solid colour
    glyphs.AmbientColor = glyphs.DiffuseColor = [0.1, 0.3, 0.9]
# The tools (a tool scene's .xmf holds a block per tool after the body's): their outlines in black.
data = servermanager.Fetch(warp)
tools = []
if data.IsA("vtkMultiBlockDataSet"):
    tools = [data.GetMetaData(i).Get(data.NAME()).split("[")[0] for i in range(1, data.GetNumberOfBlocks())]
if tools:
    # (block selectors by position: the reader's block names carry the step, "V-die[9]")
    outline = Show(ExtractBlock(Input=warp, Selectors=[f"/Root/*[{i + 2}]" for i in range(len(tools))]), view)
    outline.ColorArrayName = ["POINTS", ""]
    outline.AmbientColor = outline.DiffuseColor = [0, 0, 0]
    outline.LineWidth = 3
view.ResetCamera()
SaveScreenshot(png, view, ImageResolution=[900, 800])
print(f"paraview_render: {png} (lambda {lam:g}, time {t:g}, {field}{', contact forces' if 'contact_force' in names else ''}"
      f"{', tools ' + ', '.join(tools) if tools else ''})")
