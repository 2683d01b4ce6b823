"""The same draw on real OpenGL, to hold :func:`interp.rasterize` to account.

Uses moderngl with a headless EGL context; on Debian that is Mesa's llvmpipe software renderer
(packages ``libegl1`` and ``libgl1-mesa-dri``). Install the extra with ``pip install
"interp[gl]"``. The vertex shader passes clip coordinates straight through, so OpenGL clips,
divides, maps to the viewport and interpolates exactly as the specification says; or, with
``vertex_divide=True``, it makes the classic mistake of dividing by w itself and writing w = 1
(see :mod:`interp.shaders`). Outputs can be ``smooth``, ``noperspective`` or ``flat`` (with
OpenGL's default provoking vertex, the last).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from interp import _checks
from interp.raster import _check_scene

#: Attribute components OpenGL carries here (one vec4 varying).
MAX_COMPONENTS = 4

_VERTEX = """
#version 330
in vec4 in_clip;
in vec4 in_attribute;
{qualifier} out vec4 value;
void main() {{
    gl_Position = {position};
    value = in_attribute;
}}
"""

#: What the vertex shader writes: clip coordinates as given, or divided by w (the mistake).
_POSITIONS = {False: "in_clip", True: "vec4(in_clip.xyz / in_clip.w, 1.0)"}

#: The GLSL qualifier of each mode.
_QUALIFIERS = {"perspective": "smooth", "affine": "noperspective", "flat": "flat"}

_FRAGMENT = """
#version 330
{qualifier} in vec4 value;
layout(location = 0) out vec4 out_attribute;
layout(location = 1) out vec4 out_info;   // (triangle index, window depth, 1 = covered, 0)
void main() {{
    out_attribute = value;
    out_info = vec4(float(gl_PrimitiveID), gl_FragCoord.z, 1.0, 0.0);
}}
"""


@dataclass(frozen=True)
class GLImage:
    """What OpenGL drew. Images: row 0 at the top, like :func:`interp.rasterize`.

    Attributes
    ----------
    values : (H, W, K) float32 array
        The interpolated attributes, 0 where nothing was drawn.
    covered : (H, W) bool array
    triangle : (H, W) int array
        ``gl_PrimitiveID`` of the visible triangle, -1 where nothing was drawn.
    depth : (H, W) float32 array
        ``gl_FragCoord.z``, 1 where nothing was drawn.
    """

    values: np.ndarray
    covered: np.ndarray
    triangle: np.ndarray
    depth: np.ndarray


@cache
def context() -> Any:
    """A shared headless OpenGL 3.3+ context (EGL). Raises RuntimeError if none can be made."""
    try:
        import moderngl
    except ImportError as error:  # pragma: no cover - depends on the install
        raise RuntimeError('moderngl is not installed: pip install "interp[gl]"') from error
    try:
        return moderngl.create_standalone_context(backend="egl")
    except Exception as error:  # pragma: no cover - depends on the machine
        raise RuntimeError(
            "no headless OpenGL context (EGL); on Debian: apt-get install libegl1 libgl1-mesa-dri"
        ) from error


def renderer() -> str:
    """The GL_RENDERER string, e.g. ``'llvmpipe (LLVM 15.0.6, 256 bits)'``."""
    return context().info["GL_RENDERER"]


class Renderer:
    """A reusable OpenGL draw of one size and mode (shaders and buffers made once).

    Examples
    --------
    >>> gl = Renderer(4, 4, "perspective")
    >>> image = gl.draw([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]], [[1.0]] * 3, [[0, 1, 2]])
    >>> image.values[..., 0]
    array([[1., 1., 1., 1.],
           [1., 1., 1., 1.],
           [1., 1., 1., 1.],
           [1., 1., 1., 1.]], dtype=float32)
    """

    def __init__(
        self, width: int, height: int, mode: str = "perspective", vertex_divide: bool = False
    ) -> None:
        self.width = _checks.positive_int(width, "width")
        self.height = _checks.positive_int(height, "height")
        mode = _checks.choice(mode, "mode", tuple(_QUALIFIERS))
        if not isinstance(vertex_divide, bool):
            raise TypeError("vertex_divide must be True or False")
        qualifier = _QUALIFIERS[mode]
        ctx = self.ctx = context()
        self.program = ctx.program(
            vertex_shader=_VERTEX.format(qualifier=qualifier, position=_POSITIONS[vertex_divide]),
            fragment_shader=_FRAGMENT.format(qualifier=qualifier),
        )
        size = (self.width, self.height)
        self._attribute = ctx.texture(size, 4, dtype="f4")
        self._info = ctx.texture(size, 4, dtype="f4")
        self._depth = ctx.depth_texture(size)
        self.framebuffer = ctx.framebuffer([self._attribute, self._info], self._depth)

    def draw(self, clip: object, attributes: object, triangles: object) -> GLImage:
        """Draw the triangles and read both buffers back."""
        clip, attributes, triangles = _check_scene(clip, attributes, triangles)
        k = attributes.shape[1]
        if k > MAX_COMPONENTS:
            raise ValueError(f"attributes must have at most {MAX_COMPONENTS} columns, got {k}")
        self.render(clip, attributes, triangles)
        return self.read(k)

    def render(self, clip: np.ndarray, attributes: np.ndarray, triangles: np.ndarray) -> None:
        """Issue the draw (no read-back). Arguments as checked by :meth:`draw`."""
        ctx = self.ctx
        padded = np.zeros((len(attributes), 4), dtype="f4")
        padded[:, : attributes.shape[1]] = attributes
        buffers = [
            ctx.buffer(clip.astype("f4").tobytes()),
            ctx.buffer(padded.tobytes()),
            ctx.buffer(triangles.astype("i4").tobytes()),
        ]
        vao = ctx.vertex_array(
            self.program,
            [(buffers[0], "4f", "in_clip"), (buffers[1], "4f", "in_attribute")],
            index_buffer=buffers[2],
            index_element_size=4,
        )
        self.framebuffer.use()
        ctx.viewport = (0, 0, self.width, self.height)
        ctx.enable(ctx.DEPTH_TEST)
        ctx.disable(ctx.CULL_FACE)
        ctx.depth_func = "<"
        ctx.provoking_vertex = ctx.LAST_VERTEX_CONVENTION  # OpenGL's default, said out loud
        self.framebuffer.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        if len(triangles):
            vao.render(mode=ctx.TRIANGLES, vertices=3 * len(triangles))
        vao.release()
        for buffer in buffers:
            buffer.release()

    def read(self, k: int) -> GLImage:
        """Read the attribute and info buffers back as images (row 0 at the top)."""
        shape = (self.height, self.width, 4)
        attribute = np.frombuffer(self._attribute.read(), dtype="f4").reshape(shape)[::-1]
        info = np.frombuffer(self._info.read(), dtype="f4").reshape(shape)[::-1]
        covered = info[..., 2] > 0.5
        return GLImage(
            values=np.ascontiguousarray(attribute[..., :k]),
            covered=np.ascontiguousarray(covered),
            triangle=np.where(covered, np.rint(info[..., 0]).astype(np.int64), -1),
            depth=np.where(covered, info[..., 1], np.float32(1.0)),
        )

    def release(self) -> None:
        """Free the GPU objects."""
        for thing in (self.framebuffer, self._attribute, self._info, self._depth, self.program):
            thing.release()


def render(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    mode: str = "perspective",
    vertex_divide: bool = False,
) -> GLImage:
    """Draw once with OpenGL: the counterpart of :func:`interp.rasterize`.

    Parameters are those of :func:`interp.rasterize` (``mode`` is ``"perspective"`` for GLSL
    ``smooth``, ``"affine"`` for ``noperspective``, or ``"flat"``; at most 4 attribute columns),
    and ``vertex_divide``: the vertex shader divides by w itself and writes w = 1 (the
    counterpart of :func:`interp.shaders.shade` with ``divided=True``). Values come back as
    float32, OpenGL's precision.

    Examples
    --------
    >>> import interp
    >>> scene = interp.ground_plane(height=1.0, pitch=30.0)
    >>> gl = render(scene.clip, scene.uv, scene.triangles, 64, 48)
    >>> ours, covered = interp.rasterize(scene.clip, scene.uv, scene.triangles, 64, 48)
    >>> bool(np.array_equal(gl.covered, covered))
    True
    >>> float(np.abs(gl.values - ours)[covered].max()) < 1e-5
    True
    """
    gl = Renderer(width, height, mode, vertex_divide)
    try:
        return gl.draw(clip, attributes, triangles)
    finally:
        gl.release()


# ---------------------------------------------------------------- textures: mipmaps, trilinear

_TEXTURED_FRAGMENT = """
#version 330
{qualifier} in vec4 value;
uniform sampler2D image;
layout(location = 0) out vec4 out_attribute;  // (texture(image, uv).r, u, v, 0)
layout(location = 1) out vec4 out_info;
void main() {{
    out_attribute = vec4(texture(image, value.xy).r, value.xy, 0.0);
    out_info = vec4(float(gl_PrimitiveID), gl_FragCoord.z, 1.0, 0.0);
}}
"""


class TexturedRenderer(Renderer):
    """A :class:`Renderer` whose pixels show a mipmapped texture, sampled by GLSL ``texture()``
    at the interpolated (u, v), with ``GL_LINEAR_MIPMAP_LINEAR`` (trilinear) minification,
    ``GL_LINEAR`` magnification and ``GL_REPEAT`` wrapping: the counterpart of
    :func:`interp.mipmap.sample_trilinear`.

    Parameters
    ----------
    width, height : int
        Image size.
    levels : list of (n, n) arrays
        The mipmap pyramid, e.g. from :func:`interp.mipmap.mipmap`; uploaded as one-channel
        float32 levels (``GL_R32F``).
    mode : {"perspective", "affine"}
        How (u, v) are interpolated.
    generate : bool
        Upload only ``levels[0]`` and let ``glGenerateMipmap`` make the rest.

    Notes
    -----
    :meth:`draw` returns a :class:`GLImage` whose ``values`` hold, per pixel, the filtered
    texture value and then u and v.

    Examples
    --------
    >>> from interp.mipmap import checker_texture, mipmap
    >>> gl = TexturedRenderer(4, 4, mipmap(checker_texture(2, 4)))
    >>> image = gl.draw([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]],
    ...                 [[0, 0], [2, 0], [0, 2]], [[0, 1, 2]])
    >>> image.values[..., 0]       # one texel per pixel: level 0, sampled at texel centres
    array([[1., 1., 0., 0.],
           [1., 1., 0., 0.],
           [0., 0., 1., 1.],
           [0., 0., 1., 1.]], dtype=float32)
    >>> gl.release()
    """

    def __init__(
        self,
        width: int,
        height: int,
        levels: list[np.ndarray],
        mode: str = "perspective",
        generate: bool = False,
    ) -> None:
        import moderngl

        mode = _checks.choice(mode, "mode", ("perspective", "affine"))
        super().__init__(width, height, mode)
        qualifier = _QUALIFIERS[mode]
        self.program.release()
        self.program = self.ctx.program(
            vertex_shader=_VERTEX.format(qualifier=qualifier, position=_POSITIONS[False]),
            fragment_shader=_TEXTURED_FRAGMENT.format(qualifier=qualifier),
        )
        base = np.ascontiguousarray(levels[0], dtype="f4")
        self.texture = self.ctx.texture(base.shape[::-1], 1, base.tobytes(), dtype="f4")
        self.texture.build_mipmaps()  # glGenerateMipmap: allocates every level
        if not generate:
            for k, level in enumerate(levels[1:], start=1):
                self.texture.write(np.ascontiguousarray(level, dtype="f4").tobytes(), level=k)
        self.texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
        self.texture.repeat_x = self.texture.repeat_y = True

    def level(self, k: int) -> np.ndarray:
        """Level k of the texture as OpenGL holds it, read back (row j: v in [j, j+1)/n)."""
        n = max(self.texture.width >> k, 1)
        return np.frombuffer(self.texture.read(level=k), dtype="f4").reshape(n, n)

    def render(self, clip: np.ndarray, attributes: np.ndarray, triangles: np.ndarray) -> None:
        """Bind the texture, then draw as :meth:`Renderer.render`."""
        self.texture.use(location=0)
        super().render(clip, attributes, triangles)

    def release(self) -> None:
        """Free the GPU objects."""
        self.texture.release()
        super().release()


def render_textured(
    clip: object,
    uv: object,
    triangles: object,
    width: int,
    height: int,
    levels: list[np.ndarray],
    mode: str = "perspective",
    generate: bool = False,
) -> GLImage:
    """Draw once with a mipmapped, trilinear texture: the counterpart of
    :func:`interp.mipmap.filtering_views`. Arguments as :class:`TexturedRenderer` and
    :func:`render`; ``values[..., 0]`` is the filtered texture.

    Examples
    --------
    >>> import interp
    >>> from interp.mipmap import checker_texture, mipmap
    >>> scene = interp.ground_plane(height=1.0, pitch=20.0, size=4.0)
    >>> image = render_textured(scene.clip, scene.uv, scene.triangles, 64, 48,
    ...                         mipmap(checker_texture(8)))
    >>> bool(image.covered.any()), float(image.values[..., 0].max()) <= 1.0
    (True, True)
    """
    gl = TexturedRenderer(width, height, levels, mode, generate)
    try:
        return gl.draw(clip, uv, triangles)
    finally:
        gl.release()
