"""Camera controls, shared by every app with a camera."""

from __future__ import annotations

import ipywidgets as widgets

from interp.apps._app import slider
from interp.camera import Camera
from interp.scenes import LESSON_CAMERA

#: The camera's sliders: (low, high, step, description); near moves in powers of ten.
RANGES = {
    "height": (-0.5, 4.0, 0.01, "height"),
    "pitch": (-10.0, 90.0, 0.5, "pitch (deg)"),
    "yaw": (-180.0, 180.0, 1.0, "yaw (deg)"),
    "distance": (0.0, 8.0, 0.05, "distance"),
    "fovy": (10.0, 120.0, 1.0, "field of view (deg)"),
    "near": (0.001, 1.0, 0.05, "near plane"),
    "roll": (-180.0, 180.0, 1.0, "roll (deg)"),
}


def camera_controls(
    camera: Camera = LESSON_CAMERA, roll: bool = False
) -> dict[str, widgets.ValueWidget]:
    """Sliders for height, pitch, yaw, distance, field of view and near plane (and roll)."""
    names = [*RANGES] if roll else [n for n in RANGES if n != "roll"]
    controls = {}
    for name in names:
        low, high, step, description = RANGES[name]
        value = getattr(camera, name)
        controls[name] = slider(
            value,
            low,
            high,
            step,
            description,
            log=name == "near",
            readout_format=".3f" if name == "near" else ".2f",
        )
    return controls


def camera_from(values: dict[str, object], base: Camera = LESSON_CAMERA) -> Camera:
    """The camera the sliders describe (other fields from ``base``)."""
    fields = {name: float(values[name]) for name in RANGES if name in values}
    return Camera(**{**base.__dict__, **fields})
