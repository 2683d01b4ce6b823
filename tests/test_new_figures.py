"""Lesson 7's and 8's figures shown with ``apps.App(registry.X)`` (not in ``apps.ALL``): any
control values show a clean figure and a readout (tests/test_live.py checks their frames)."""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from interp.apps import App
from interp.plots import registry

from helpers import shown_arrays

NEW = [registry.LinearOnScreen, registry.Shader]


def values_of(control):
    if isinstance(control, widgets.Dropdown):
        return st.sampled_from(list(control.options))
    if isinstance(control, widgets.FloatLogSlider):
        return st.floats(control.min, control.max).map(lambda e: 10.0**e)
    return st.floats(control.min, control.max)


@pytest.mark.parametrize("figure_class", NEW, ids=lambda c: c.name)
def test_any_control_values_show_a_clean_figure_and_a_readout(figure_class):
    app = App(figure_class)

    @settings(max_examples=25, deadline=None)
    @given(st.fixed_dictionaries({k: values_of(c) for k, c in app.controls.items()}))
    def fuzz(values):
        app.set(**values)
        for array in shown_arrays(app.figure):
            assert np.all(np.isfinite(array))
        assert app.plot.readout()

    fuzz()
    for camera in (
        {"height": 0.0, "pitch": 0.0},
        {"height": 0.001, "pitch": -10.0, "near": 0.001},
        {"height": -0.5, "pitch": 30.0},
        {"height": 4.0, "pitch": 90.0, "distance": 0.0},
        {"height": 0.5, "distance": 0.0, "pitch": 5.0, "near": 0.001},
    ):
        app.set(**camera)
        for array in shown_arrays(app.figure):
            assert np.all(np.isfinite(array))
        assert app.plot.readout()
