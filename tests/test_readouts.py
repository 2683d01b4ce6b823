"""Every figure's readout (its key result as text, shown beside the app and used as alt text) is
non-empty and true: each number in it is recomputed here from the library, independently of the
plot that drew it, at the defaults and at settings the lessons' prompts ask for."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.figure import Figure

import interp
from interp import approximation, depth, lerp, mipmap, mistakes, shaders, theory
from interp.plots.attributes import CORNER_COLOURS
from interp.plots.gpu import LAB_CAMERA, SHADER_COLOURS
from interp.plots.params import camera_from
from interp.plots.planes import verdict
from interp.plots.registry import FIGURES, RESOLUTIONS
from interp.scenes import LESSON_SIZE, checker_views


def _camera(p, width, height):
    return camera_from(p).fitted(width, height)


def the_problem(p):
    a = p["d"] * p["A_x"] / p["A_w"]
    b = p["d"] * p["B_x"] / p["B_w"]
    if a == b:
        return ["single point", "s is undefined", "c = 0"]
    s = p["B_w"] / (p["A_w"] + p["B_w"])  # s_from_t(1/2), by hand
    words = "its middle:" if p["A_w"] == p["B_w"] else "not at its middle"
    return [f"s = {s:.3f}", words]


def projecting_a_line(p):
    # cast each pixel's ray and intersect it with AB: no t_from_s
    n, d = p["samples"], p["d"]
    A, B = np.array([p["A_x"], p["A_w"]]), np.array([p["B_x"], p["B_w"]])
    a, b = d * A[0] / A[1], d * B[0] / B[1]
    near = 0
    for s in (np.arange(n) + 0.5) / n:
        ray = np.array([(1 - s) * a + s * b, d])  # (x, w) of the pixel on the image plane
        _, t = np.linalg.solve(np.column_stack([ray, A - B]), A)  # k ray = A + t (B - A)
        near += t < 0.5
    return [
        f"{near} of the {n} equally spaced pixel",
        f"s = {p['B_w'] / (p['A_w'] + p['B_w']):.3f}",
    ]


def st_mapping(p):
    w1, w2 = p["w1"], p["w2"]
    if w1 == w2:
        return ["diagonal", "0 everywhere"]
    r = np.sqrt(w2 / w1)
    s = np.linspace(0, 1, 2001)
    gap = np.abs(lerp.t_from_s(s, w1, w2) - s)
    return [f"s* = {r / (1 + r):.3f}", f"it is {abs(r - 1) / (r + 1):.3f}", f"{gap.max():.3f}"]


def depth_figure(p):
    near, far, buffer = p["near"], p["far"], p["buffer"]
    steps = [depth.depth_step(w, near, far, buffer) for w in (1.0, 0.9 * far)]
    said = [f"{steps[0]:.3g} at w = 1", f"{steps[1]:.3g} at w = {0.9 * far:g}", buffer]
    s = np.linspace(0, 1, 100001)
    w = 1 / ((1 - s) / p["w1"] + s / p["w2"])
    outside = (w < near) | (w > far)
    if outside.all():
        said.append("it is clipped")
    elif outside.any():
        low, high = s[outside].min(), s[outside].max()
        said.append(f"from s = {low:.2f} to {high:.2f} is clipped")
    return said


def attributes(p):
    s = 0.5
    right = lerp.lerp_perspective(p["a1"], p["a2"], p["w1"], p["w2"], s)
    window = mistakes.lerp_with_window_z(p["a1"], p["a2"], p["w1"], p["w2"], s, p["near"], 20.0)
    early = mistakes.lerp_divided_too_early(p["a1"], p["a2"], p["w1"], p["w2"], s)
    t_c = (p["w1"] - p["near"]) / (p["w1"] - p["behind"])
    a_c = p["a1"] + t_c * (p["a2"] - p["a1"])
    return [
        f"right attribute is {right:.3f}",
        f"gives {(p['a1'] + p['a2']) / 2:.3f}",
        f"window z {window:.3f}",
        f"too early {early:.3f}",
        f"C must get {a_c:.3f}",
    ]


def _colour_difference(p, triangles_of, colours, width=240, height=180):
    scene = interp.ground_plane(_camera(p, width, height), LESSON_SIZE, quads=1)
    triangles = triangles_of(scene)
    images = [
        interp.rasterize(scene.clip, colours, triangles, width, height, mode)
        for mode in ("affine", "perspective")
    ]
    covered = images[0][1]
    if not covered.any():
        return None
    shown = [np.clip(values, 0, 1) for values, _ in images]
    return float(np.abs(shown[0] - shown[1])[covered].max())


def colour_quad(p):
    largest = _colour_difference(p, lambda scene: scene.triangles, CORNER_COLOURS)
    if largest is None:
        return ["out of view"]
    return ["agree"] if largest < 0.005 else [f"up to {largest:.2f}"]


def barycentrics(p):
    largest = _colour_difference(p, lambda scene: scene.triangles[:1], CORNER_COLOURS)
    scene = interp.ground_plane(_camera(p, 240, 180), LESSON_SIZE, quads=1)
    depths = ", ".join(f"{w:.2f}" for w in scene.clip[scene.triangles[0], 3])
    if largest is None:
        return ["out of view", depths]
    return [depths, "agree" if largest < 0.005 else f"up to {largest:.2f}"]


def checkerboards(p):
    width, height = RESOLUTIONS[p["resolution"]]
    scene = interp.ground_plane(_camera(p, width, height), LESSON_SIZE, quads=p["quads"])
    views = checker_views(
        scene,
        width,
        height,
        p["frequency"],
        p["filtered"] == "filtered",
        mode=p["mode"],
        span=p["span"],
    )
    if not views.covered.any():
        return ["out of view"]
    largest = views.error[views.covered].max()
    if largest < 0.005:
        return ["nothing to see"]
    row = int(np.argmax(np.where(views.covered, views.error, -1).max(axis=1)))
    return [f"Largest error {largest:.2f} texels", f"row {row}"]


def uv_images(p):
    scene = interp.ground_plane(_camera(p, 240, 180), LESSON_SIZE, quads=1)
    affine, covered = interp.rasterize(scene.clip, scene.uv, scene.triangles, 240, 180, "affine")
    right, _ = interp.rasterize(scene.clip, scene.uv, scene.triangles, 240, 180)
    if not covered.any():
        return ["out of view"]
    du, dv = np.abs(affine - right)[covered].max(axis=0)
    return [f"{du:.3f} in u", f"{dv:.3f} in v", p["mode"]]


def linear_on_screen(p):
    truth = theory.ground_truth(camera_from(p), 240, 180)
    if not truth.covered.any():
        return ["out of view"]
    return [f"{name} {verdict(theory.misfits(truth, name))}" for name in (p["left"], p["right"])]


def shader(p):
    camera = _camera(p, 240, 180)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=1)
    draw = {
        q: shaders.shade(scene.clip, SHADER_COLOURS, scene.triangles, 240, 180, q)
        for q in ("smooth", "noperspective", "flat")
    }
    output = p["output"]
    if output.startswith("smooth"):
        draw[output] = shaders.shade(
            scene.clip, SHADER_COLOURS, scene.triangles, 240, 180, "smooth", divided=True
        )
    values, covered = draw[output]
    if not covered.any():
        return ["out of view"]
    behind = int(np.sum(scene.clip[:, 3] <= 0))
    if output.startswith("smooth") and behind:
        return [f"{behind} corner", f"covers {covered.sum()} pixels", f"{draw['smooth'][1].sum()}"]
    both = covered & draw["smooth"][1]
    from_smooth = np.abs(np.clip(values, 0, 1) - np.clip(draw["smooth"][0], 0, 1))[both].max()
    beyond = max(values[covered].max() - 1, -values[covered].min())
    if output == "noperspective" and beyond >= 0.005:
        return [f"{from_smooth:.2f}", f"run up to {beyond:.2f} past the corners' range"]
    return [f"{from_smooth:.2f}"]


def _clipped(p):
    """The ground at 320 x 240: the scene, how many triangles show, and as how many pieces."""
    scene = interp.ground_plane(_camera(p, 320, 240), LESSON_SIZE, quads=p["quads"])
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 320, 240)
    return scene, len(np.unique(frags.clipped.source)), len(frags.clipped)


def clipping(p):
    scene, visible, pieces = _clipped(p)
    return [
        f"{visible} triangles in view became {pieces}",
        f"{int(np.sum(scene.clip[:, 3] <= 0))} of the ground's {len(scene.clip)} vertices",
    ]


def approximations(p):
    camera = camera_from(p, LAB_CAMERA)
    spans = approximation.span_costs(camera, 192, 144, 8)
    tess = approximation.tessellation_costs(camera, 192, 144, 8)
    k, j = list(spans.setting).index(16), list(tess.setting).index(8)
    if spans.divides_per_pixel[k] == 0:
        return ["out of view"]

    def texels(error):  # an exact method's error is rounding: said as 0
        return "0 (to rounding)" if error < 1e-9 else f"{error:.3g}"

    return [
        f"mean error {texels(spans.mean_error[k])} texels at {spans.divides_per_pixel[k]:.3f}",
        f"{texels(tess.mean_error[j])} texels at {tess.divides_per_pixel[j]:.3f}",
    ]


def _rays_that_hit(camera, width, height, quads, per_side=3):
    """How many of the outside view's pixel rays meet the quad, from the rasterizer's coverage
    at their pixels (per_side x per_side pixels spread evenly over the image)."""
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=quads)
    _, covered = interp.rasterize(scene.clip, scene.uv, scene.triangles, width, height)
    spread = (np.arange(per_side) + 0.5) / per_side
    columns = np.floor(spread * width).astype(int)
    rows = height - 1 - np.floor(spread * height).astype(int)  # window y is up, rows go down
    return int(covered[np.ix_(rows, columns)].sum()), per_side**2


def _eye(p, width=320, height=240):
    camera = _camera(p, width, height)
    side = "above" if p["height"] >= 0 else "below"
    hits, rays = _rays_that_hit(camera, width, height, p["quads"], p.get("rays", 3))
    return [
        f"The eye is {abs(p['height']):.2f} {side} the ground, {p['distance']:.2f} from",
        f"{hits} of {rays} pixel rays meet the quad",
    ]


def _near_cuts(p, width=320, height=240):
    camera = _camera(p, width, height)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=p["quads"])
    # a plane's depth is linear, so some of it is nearer than near iff a vertex is
    cut = np.any(scene.clip[:, 3] < camera.near)
    return "the near plane cuts part of the quad off" if cut else "the near plane cuts nothing off"


def outside_view(p):
    _, visible, pieces = _clipped(p)
    return [
        *_eye(p),
        f"keeps {visible} of {2 * p['quads'] ** 2} triangles as {pieces} pieces",
        _near_cuts(p),
    ]


def checkerboards_outside(p):
    width, height = RESOLUTIONS[p["resolution"]]
    return checkerboards(p) + _eye(p, width, height)


def clipping_outside(p):
    return [*clipping(p), _near_cuts(p)]


def texture_filtering(p):
    camera = _camera(p, 320, 240)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=p["quads"])
    views = mipmap.filtering_views(scene, 320, 240, int(p["frequency"]), mode=p["mode"])
    if not views.fragments.covered.any():
        return ["out of view"]
    low, high = views.lod.min(), views.lod.max()
    deepest = 0 if high <= 0 else min(int(np.floor(high)) + 1, 8)  # 256 texels: 8 levels down
    return [
        f"λ runs from {low:.2f} to {high:.2f}",
        f"{np.mean(views.lod <= 0):.0%} of the drawn pixels are magnified",
        f"down to mipmap level {deepest}",
    ]


def mipmap_pyramid(p):
    f = int(p["frequency"])
    sharp = int(np.log2(256 // f))  # the level with one texel a check
    return [f"{f} x {f} checks of {256 // f} texels", f"level {sharp} still", f"level {sharp + 1}"]


#: For each figure: what its readout must say, and the settings to try besides the defaults.
CHECKS = {
    "the-problem": (
        the_problem,
        [{"A_w": 3.0, "B_w": 3.0}, {"A_x": -1.0, "A_w": 2.0, "B_x": -2.0, "B_w": 4.0}, {"d": 3.0}],
    ),
    "projecting-a-line": (projecting_a_line, [{"A_w": 8.0, "B_w": 2.0}, {"samples": 32}]),
    "st-mapping": (st_mapping, [{"w2": 1.0}, {"w1": 1.0, "w2": 9.0}, {"w1": 0.1, "w2": 10.0}]),
    "depth": (
        depth_figure,
        [{"far": 5.0}, {"near": 0.01, "buffer": "float32 reversed"}, {"w1": 0.2, "near": 0.5}],
    ),
    "attributes": (attributes, [{"w2": 1.0}, {"near": 0.86}, {"behind": -10.0, "a1": 0.3}]),
    "colour-quad": (
        colour_quad,
        [{"pitch": 90.0, "distance": 0.0}, {"pitch": -10.0, "height": 4.0}],
    ),
    "checkerboards": (
        checkerboards,
        [
            {"distance": 0.0, "pitch": 90.0},
            {"pitch": 90.0},
            {"mode": "subdivided", "roll": 30.0, "span": 64},
            {"quads": 8, "resolution": "160 x 120"},
        ],
    ),
    "uv-images": (uv_images, [{"mode": "affine", "yaw": 45.0}, {"pitch": 90.0}]),
    "linear-on-screen": (
        linear_on_screen,
        [
            {"left": "u", "right": "u/w"},
            {"pitch": 90.0, "distance": 0.0},
            {"left": "NDC z", "right": "w", "roll": 0.0},
        ],
    ),
    "barycentrics": (barycentrics, [{"pitch": 90.0, "distance": 0.0, "height": 2.2}]),
    "shader": (
        shader,
        [
            {"output": "flat"},
            {"output": "noperspective"},
            {"height": 0.3, "distance": 1.0},
            {"height": 0.3, "distance": 1.0, "output": "noperspective"},  # corners behind
        ],
    ),
    "clipping": (clipping, [{"height": -0.5}, {"height": 0.0}, {"distance": 0.0, "near": 0.01}]),
    "approximations": (approximations, [{"roll": 0.0}, {"pitch": -10.0, "height": 4.0}]),
    "outside-view": (
        outside_view,
        [
            {"pitch": 90.0},
            {"height": -0.5},
            {"height": 0.3, "distance": 1.0, "quads": 2},
            {"height": 0.0},  # in the ground's plane: every piece edge-on, none drawn
        ],
    ),
    "checkerboards-outside": (
        checkerboards_outside,
        [{"pitch": 90.0}, {"height": 0.3, "distance": 1.0}, {"resolution": "160 x 120"}],
    ),
    "clipping-outside": (
        clipping_outside,
        [
            {"height": 0.05},
            {"height": -0.5},
            {"distance": 0.0, "pitch": 90.0, "height": 2.0},
            {"height": 0.0},
        ],
    ),
    "texture-filtering": (
        texture_filtering,
        [
            {"height": 2.0, "pitch": 90.0, "distance": 0.0},
            {"mode": "affine"},
            {"frequency": "128", "pitch": 11.0},
            {"pitch": 90.0},
        ],
    ),
    "mipmap-pyramid": (mipmap_pyramid, [{"frequency": "2"}, {"frequency": "128"}]),
}


def test_every_figure_is_checked():
    assert set(CHECKS) == set(FIGURES)


CASES = [
    (name, settings)
    for name, (_, extra) in CHECKS.items()
    for settings in [{}, *extra]
    if all(k in FIGURES[name].PARAMS for k in settings)
]


@pytest.mark.parametrize(("name", "settings"), CASES, ids=[f"{n} {s}" for n, s in CASES])
def test_the_readout_is_true(name, settings):
    figure_class = FIGURES[name]
    shown = figure_class(Figure(figsize=figure_class.size), **settings)
    text = shown.readout()
    assert text and text.strip() == text and text.endswith(".")
    assert len(text) < 400, "one or two sentences"
    for part in CHECKS[name][0]({**figure_class.defaults(), **settings}):
        assert part in text, (part, text)


@pytest.mark.parametrize("name", list(FIGURES))
def test_the_readout_follows_the_figure(name):
    """Built at the defaults and updated to another setting, a figure says what one built at that
    setting says."""
    figure_class = FIGURES[name]
    extra = next(s for s in CHECKS[name][1] if all(k in figure_class.PARAMS for k in s))
    updated = figure_class(Figure(figsize=figure_class.size))
    updated.update(**extra)
    direct = figure_class(Figure(figsize=figure_class.size), **extra)
    assert updated.readout() == direct.readout()
