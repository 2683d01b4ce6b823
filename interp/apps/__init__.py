"""Live figures for the lessons: sliders wired to :mod:`interp.plots`, no math here.

Each function returns an app; show it by leaving it as the last expression of a cell. With
``%matplotlib widget`` (ipympl) the figure updates in place as the sliders move; without it,
the same call shows a static figure that is redrawn after each change.

=====================  =====================================================================
lesson                 apps
=====================  =====================================================================
1 the problem          :func:`the_problem`
2 projecting a line    :func:`projecting_a_line`
3 the s-t mapping      :func:`st_mapping`
4 depth                :func:`depth`
5 attributes           :func:`attributes`, :func:`colour_quad`
6 checkerboards        :func:`checkerboards`, :func:`uv_images`
7 triangles and GPUs   :func:`barycentrics`, :func:`clipping`, :func:`approximations`
=====================  =====================================================================

:func:`presentation` makes later apps larger, for a projector.
"""

from interp.apps._app import App, presentation
from interp.apps.line import projecting_a_line, st_mapping, the_problem
from interp.apps.scenes import (
    approximations,
    attributes,
    barycentrics,
    checkerboards,
    clipping,
    colour_quad,
    depth,
    uv_images,
)

#: Every app, by name, for tests and the handout exporter.
ALL = {
    "the_problem": the_problem,
    "projecting_a_line": projecting_a_line,
    "st_mapping": st_mapping,
    "depth": depth,
    "attributes": attributes,
    "colour_quad": colour_quad,
    "checkerboards": checkerboards,
    "uv_images": uv_images,
    "barycentrics": barycentrics,
    "clipping": clipping,
    "approximations": approximations,
}

__all__ = [
    "ALL",
    "App",
    "approximations",
    "attributes",
    "barycentrics",
    "checkerboards",
    "clipping",
    "colour_quad",
    "depth",
    "presentation",
    "projecting_a_line",
    "st_mapping",
    "the_problem",
    "uv_images",
]
