"""The package leaves every other package as it found it: the live apps run on public APIs
only, and no module or class attribute of matplotlib, ipympl, ipywidgets, traitlets,
jupyter_server, IPython or numpy is replaced, wrapped or added."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: Run in a fresh interpreter: import the packages the apps use, note every attribute of each
#: of their modules and classes, import interp and run every app through slider steps on
#: ipympl's canvas, then report what is no longer the same object (or is new).
PROBE = r"""
import json, sys, warnings
warnings.simplefilter("ignore")
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
import IPython, ipywidgets, ipympl.backend_nbagg, matplotlib.pyplot, numpy, traitlets
import matplotlib.backends.backend_agg, matplotlib.backends.backend_webagg_core
import jupyter_server.services.kernels.websocket, jupyter_server.services.kernels.kernelmanager
import mpl_toolkits.mplot3d, PIL.Image, PIL.PngImagePlugin
import tornado.web

PACKAGES = ("matplotlib", "mpl_toolkits", "ipympl", "ipywidgets", "traitlets", "jupyter_server",
            "IPython", "numpy", "PIL", "tornado", "comm", "ipykernel")

def namespaces():
    for name, module in list(sys.modules.items()):
        if module is None or name.split(".")[0] not in PACKAGES:
            continue
        yield name, module
        for attr, value in list(vars(module).items()):
            if isinstance(value, type) and getattr(value, "__module__", None) == name:
                yield f"{name}.{attr}", value

def snapshot():
    return {where: dict(vars(space)) for where, space in namespaces()}

# Work any notebook does first, so that the packages' own lazy caches (a unit circle, a
# mathtext parser, pyplot's backend module, Pillow's plugins, the comm manager) are filled.
fig = matplotlib.pyplot.figure()
ax = fig.add_subplot(1, 2, 1)
ax.plot([0, 1], [0, 1], "o-", label="$x^2$")
ax.imshow(numpy.zeros((2, 2)))
ax.legend()
fig.add_subplot(1, 2, 2, projection="3d").plot([0, 1], [0, 1], [0, 1])
fig.canvas.draw()
fig.savefig(__import__("io").BytesIO(), format="png")
ipywidgets.FloatSlider()
with matplotlib.pyplot.ioff():  # as ipympl's examples make a figure to put in a layout
    matplotlib.pyplot.figure()
matplotlib.pyplot.close("all")

before = snapshot()
import interp, interp.apps, interp.classroom
from interp.apps import ALL
steps = 0
for name, make in ALL.items():
    app = make()
    for key, control in app.controls.items():
        if hasattr(control, "step"):
            app.set(**{key: min(control.max, control.value + control.step)})
            app.set(**{key: max(control.min, control.value - 2 * control.step)})
            steps += 2
    app.widget  # the controls and the canvas, as shown
    matplotlib.pyplot.close("all")
changed = []
for where, space in namespaces():
    old = before.get(where)
    if old is None:
        continue  # a module first imported by interp: nothing of the user's was changed in it
    now = vars(space)
    for attr, value in old.items():
        if attr in ("__dict__", "__weakref__"):
            continue
        if now.get(attr, changed) is not value and attr not in ("_lock",):
            changed.append(f"{where}.{attr}")
    for attr in now.keys() - old.keys():
        if not isinstance(now[attr], type(sys)):  # a submodule imported: not a change
            changed.append(f"{where}.{attr} (added)")
print(json.dumps({"steps": steps, "modules": len(before), "changed": changed}))
"""

#: Attributes that change by themselves as code runs, not by anyone's patching: pyplot's own
#: bookkeeping of open figures.
MOVING = ("matplotlib._pylab_helpers.Gcf.figs",)


def changed_names(changed: list[str]) -> list[str]:
    """``changed`` less what packages change themselves: a module's ``__warningregistry__``,
    lazily filled caches, and pyplot's bookkeeping of open figures."""
    ignore = ("__warningregistry__", "__slotnames__", "_cache", "_instances", "__annotations__")
    return [
        c for c in changed if not any(part in c for part in ignore) and not c.startswith(MOVING)
    ]


def test_running_every_app_changes_no_attribute_of_another_package():
    result = subprocess.run(
        [sys.executable, "-c", PROBE],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
        check=False,
    )
    assert result.returncode == 0, result.stderr[-3000:]
    report = json.loads(result.stdout.strip().splitlines()[-1])
    assert report["steps"] > 200 and report["modules"] > 300, report
    assert changed_names(report["changed"]) == []


def test_the_package_has_no_page_script_patch_or_allocator_change():
    """The grep the issue's reviewers run: no page script, no reach into JupyterLab's module
    federation, no prototype chain walked, no allocator setting, no server handler replaced."""
    forbidden = ("_JUPYTERLAB", "mallopt", "prototype", "KernelWebsocketHandler.open =",
                 "Javascript(", "<script", "ctypes")  # fmt: skip
    found = [
        f"{path.relative_to(ROOT)}: {word}"
        for path in (ROOT / "interp").rglob("*.py")
        for word in forbidden
        if word in path.read_text()
    ]
    assert found == []
