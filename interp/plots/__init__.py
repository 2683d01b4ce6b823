"""One object per figure: give it matplotlib axes, get back something with ``update(**params)``.

The lessons' live apps (:mod:`interp.apps`) and the handout exporter draw with these same
objects; all the numbers come from the math modules.
"""

from interp.plots._style import AFFINE, CORRECT, STYLE, styled
from interp.plots.attributes import ClipVertexMistake, ColourTriangle, MistakesAlongALine
from interp.plots.checker import CheckerPanels, UVImages
from interp.plots.depth import DepthAcross, DepthPrecision
from interp.plots.filtering import FilteringPanels, MipmapPyramid
from interp.plots.gpu import ApproximationLab, ClippingView
from interp.plots.line import GapPlot, ImageStrip, LineView, STCurve, STFamily
from interp.plots.outside import OutsideView

__all__ = [
    "AFFINE",
    "CORRECT",
    "STYLE",
    "ApproximationLab",
    "CheckerPanels",
    "ClipVertexMistake",
    "ClippingView",
    "ColourTriangle",
    "DepthAcross",
    "DepthPrecision",
    "FilteringPanels",
    "GapPlot",
    "ImageStrip",
    "LineView",
    "MipmapPyramid",
    "MistakesAlongALine",
    "OutsideView",
    "STCurve",
    "STFamily",
    "UVImages",
    "styled",
]
