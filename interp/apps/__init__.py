"""Live figures for the lessons: one control per parameter of a figure, no math here.

Each function returns an app; show it by leaving it as the last expression of a cell. With
``%matplotlib widget`` (ipympl) the figure updates in place as the sliders move; without it,
the same call shows a static figure that is redrawn after each change. The figures themselves,
their parameters and captions are in :mod:`interp.plots.registry`, which ``interp-figures``
draws too.

=====================  =====================================================================
lesson                 apps
=====================  =====================================================================
1 the problem          :func:`the_problem`
2 projecting a line    :func:`projecting_a_line`
3 the s-t mapping      :func:`st_mapping`
4 depth                :func:`depth`
5 attributes           :func:`attributes`, :func:`colour_quad`
6 checkerboards        :func:`checkerboards`, :func:`checkerboards_outside`, :func:`uv_images`,
                       :func:`outside_view`
7 triangles            :func:`linear_on_screen`, :func:`barycentrics`
8 GPUs                 :func:`shader`, :func:`clipping`, :func:`clipping_outside`,
                       :func:`approximations`
9 texture filtering    :func:`texture_filtering`, :func:`mipmap_pyramid`
=====================  =====================================================================

:func:`presentation` makes later apps larger, for a projector.
"""

from __future__ import annotations

from interp.apps._app import App, presentation
from interp.apps._drag import DragEndpoints
from interp.plots import registry


def the_problem() -> App:
    """Lesson 1's app: drag A and B, change the image-plane distance d."""
    return DragEndpoints(registry.TheProblem)


def projecting_a_line() -> App:
    """Lesson 2's app: top view, attribute along the image, and s-t curve, linked."""
    return DragEndpoints(registry.ProjectingALine)


def st_mapping() -> App:
    """Lesson 3's app: the s-t curves for a depth ratio, and the gap's peak."""
    return App(registry.STMapping)


def depth() -> App:
    """Lesson 4's app: depth across the screen, and the depth buffer's precision."""
    return App(registry.Depth)


def attributes() -> App:
    """Lesson 5's app: right and wrong interpolation along a line; the clip vertex."""
    return App(registry.Attributes)


def colour_quad() -> App:
    """Lesson 5's app: a colour gradient across a quad, affine and perspective-correct."""
    return App(registry.ColourQuad)


def checkerboards() -> App:
    """Lesson 6's app: affine beside perspective-correct, and the error in texels."""
    return App(registry.Checkerboards)


def checkerboards_outside() -> App:
    """Lesson 6's app: the checkerboards beside the scene seen from outside (orbit it with the
    mouse)."""
    return App(registry.CheckerboardsOutside)


def uv_images() -> App:
    """Lesson 6's app: u and v as images."""
    return App(registry.UVImagesFigure)


def outside_view() -> App:
    """Lesson 6's app: camera, frustum, pixel rays and quad seen from outside, alone."""
    return App(registry.OutsideViewFigure)


def linear_on_screen() -> App:
    """Lesson 7's app: which quantities are planes over the screen (1/w, u/w), which not (w, u)."""
    return App(registry.LinearOnScreen)


def barycentrics() -> App:
    """Lesson 7's app: one triangle coloured by its barycentrics, screen-space and clip-space."""
    return App(registry.Barycentrics)


def shader() -> App:
    """Lesson 8's app: what a fragment shader receives, smooth beside the other qualifiers."""
    return App(registry.Shader)


def clipping() -> App:
    """Lesson 8's app: near-plane clipping as the camera moves through the plane."""
    return App(registry.Clipping)


def clipping_outside() -> App:
    """Lesson 8's app: the clipping app beside the scene seen from outside: what the near plane
    cuts off, and the vertices clipping makes."""
    return App(registry.ClippingOutside)


def approximations() -> App:
    """Lesson 8's app: the approximation lab."""
    return App(registry.Approximations)


def texture_filtering() -> App:
    """Lesson 9's app: pixel footprints in the texture, the mip level per pixel, the filtered
    image."""
    return App(registry.TextureFiltering)


def mipmap_pyramid() -> App:
    """Lesson 9's app: the checkerboard's mipmap levels."""
    return App(registry.MipmapPyramidFigure)


#: Every app, by name (the figure's name with underscores), for tests and notebooks.
ALL = {
    "the_problem": the_problem,
    "projecting_a_line": projecting_a_line,
    "st_mapping": st_mapping,
    "depth": depth,
    "attributes": attributes,
    "colour_quad": colour_quad,
    "checkerboards": checkerboards,
    "uv_images": uv_images,
    "checkerboards_outside": checkerboards_outside,
    "outside_view": outside_view,
    "linear_on_screen": linear_on_screen,
    "barycentrics": barycentrics,
    "shader": shader,
    "clipping": clipping,
    "clipping_outside": clipping_outside,
    "approximations": approximations,
    "texture_filtering": texture_filtering,
    "mipmap_pyramid": mipmap_pyramid,
}

__all__ = [
    "ALL",
    "App",
    "approximations",
    "attributes",
    "barycentrics",
    "checkerboards",
    "checkerboards_outside",
    "clipping",
    "clipping_outside",
    "colour_quad",
    "depth",
    "linear_on_screen",
    "mipmap_pyramid",
    "outside_view",
    "presentation",
    "projecting_a_line",
    "shader",
    "st_mapping",
    "texture_filtering",
    "the_problem",
    "uv_images",
]
