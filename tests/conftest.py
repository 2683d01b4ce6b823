"""Shared test set-up: headless matplotlib, hypothesis profiles, a seeded generator."""

from __future__ import annotations

import os

import matplotlib
import numpy as np
import pytest
from hypothesis import HealthCheck, settings

matplotlib.use("Agg")

settings.register_profile(
    "ci", max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile("dev", max_examples=30, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


@pytest.fixture(scope="module")
def gl():
    """:mod:`interp.opengl` with a context made: real OpenGL (Mesa's llvmpipe through EGL).
    Skipped where there is none, except under ``CI=true``, where that is a failure."""
    try:
        from interp import opengl

        opengl.context()
    except (ImportError, RuntimeError) as error:
        if os.environ.get("CI"):
            pytest.fail(f"CI must have OpenGL (EGL + Mesa): {error}")
        pytest.skip(f"no OpenGL here: {error}")
    return opengl


@pytest.fixture(scope="module")
def browser():
    """Debian's Chromium, headless, through Playwright (``tests/browser.py``). Skipped where
    there is none, except under ``CI=true``, where that is a failure."""
    from browser import chromium, need_chromium, sync_api

    playwright_api = sync_api()
    need_chromium()
    with playwright_api.sync_playwright() as playwright:
        launched = chromium(playwright)
        yield launched
        launched.close()


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(20261122)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    """Keep each phase's report on the test item, so fixtures can tell whether it failed."""
    outcome = yield
    report = outcome.get_result()
    setattr(item, f"report_{report.when}", report)
