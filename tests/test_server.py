"""The Jupyter settings the package installs, read from a real JupyterLab server installed as
``make`` installs it.

The server extension ``interp.server`` sends kernel messages over a websocket with
``TCP_NODELAY`` set.

The option is read from the server's own socket (Linux: ``pidfd_getfd`` copies the socket into
this process), for the connection a websocket client opened to a kernel, as JupyterLab's page
does. With the extension turned off the same socket has Nagle's algorithm on: tornado's
default, the cause of 15-40 ms of waiting per picture that ``interp.server`` describes.
"""

from __future__ import annotations

import asyncio
import html
import json
import re
import sys
import uuid

import pytest
from browser import nodelay_of, server, socket_inode, socket_owner
from tornado.httpclient import AsyncHTTPClient
from tornado.websocket import websocket_connect

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="reads the server's socket through Linux's /proc"
)


async def _kernel_socket_nodelay(base: str) -> int:
    """Start a kernel, open its websocket as JupyterLab does, and read the server's side."""
    client = AsyncHTTPClient()
    page = await client.fetch(base + "/lab")
    cookie = next(c for c in page.headers.get_list("Set-Cookie") if c.startswith("_xsrf="))
    cookie = cookie.split(";")[0]
    headers = {"Cookie": cookie, "X-XSRFToken": cookie.split("=", 1)[1]}
    reply = await client.fetch(base + "/api/kernels", method="POST", body="{}", headers=headers)
    kernel = json.loads(reply.body)["id"]
    channels = f"/api/kernels/{kernel}/channels?session_id={uuid.uuid4()}"
    websocket = await websocket_connect(base.replace("http", "ws", 1) + channels)
    try:
        # The server has opened its side once it sends something (a status message).
        await asyncio.wait_for(websocket.read_message(), timeout=60)
        mine = websocket.protocol.stream.socket.getsockname()[1]
        server_port = int(base.rsplit(":", 1)[1])
        return nodelay_of(*socket_owner(socket_inode(server_port, mine)))
    finally:
        websocket.close()
        await client.fetch(base + f"/api/kernels/{kernel}", method="DELETE", headers=headers)


@pytest.mark.parametrize("enabled", [True, False], ids=["installed", "turned-off"])
def test_kernel_messages_leave_the_server_without_delay(tmp_path, enabled):
    workdir = tmp_path / "w"
    if not enabled:  # the user's own config turns it off (and so shows tornado's default)
        config = workdir / "config"
        config.mkdir(parents=True)
        off = {"ServerApp": {"jpserver_extensions": {"interp.server": False}}}
        (config / "jupyter_server_config.json").write_text(json.dumps(off))
    with server("lab", workdir) as base:
        assert asyncio.run(_kernel_socket_nodelay(base)) == (1 if enabled else 0)


#: JupyterLab's plugin that swaps the tab's icon while the kernel is busy.
FAVICON_BUSY = "@jupyterlab/application-extension:faviconbusy"


def _page_config(base: str) -> dict:
    """The settings JupyterLab's page is given (its ``jupyter-config-data``)."""

    async def fetch() -> str:
        return (await AsyncHTTPClient().fetch(base + "/lab")).body.decode()

    data = re.search(
        r'<script id="jupyter-config-data" type="application/json">(.*?)</script>',
        asyncio.run(fetch()),
        re.S,
    )
    assert data, "no jupyter-config-data in JupyterLab's page"
    return json.loads(html.unescape(data.group(1)))


@pytest.mark.parametrize("enabled", [False, True], ids=["installed", "turned-on-again"])
def test_the_busy_tab_icon_is_off_unless_turned_on_again(tmp_path, enabled):
    """The package turns JupyterLab's busy tab icon off: every slider step swapped it twice,
    each swap a request to the server (``tests/test_browser.py`` counts them on a real page).
    ``jupyter labextension enable`` turns it back on: it writes a ``page_config.json``
    enabling the plugin, which outranks the package's file. Here that file is written to a
    folder on ``JUPYTER_CONFIG_PATH`` (ranked first) rather than into the test's environment."""
    workdir = tmp_path / "w"
    env = {}
    if enabled:
        labconfig = tmp_path / "on" / "labconfig"
        labconfig.mkdir(parents=True)
        on = {"disabledExtensions": {FAVICON_BUSY: False}}
        (labconfig / "page_config.json").write_text(json.dumps(on))
        env["JUPYTER_CONFIG_PATH"] = str(tmp_path / "on")
    with server("lab", workdir, env=env) as base:
        disabled = _page_config(base)["disabledExtensions"]
    assert (FAVICON_BUSY in disabled) is not enabled


def _settings(base: str, plugin: str) -> dict:
    """A plugin's settings as JupyterLab's page composes them: the user's own, else the
    schema's defaults, which the server gives with the package's overrides applied."""

    async def fetch() -> bytes:
        return (await AsyncHTTPClient().fetch(f"{base}/lab/api/settings/{plugin}")).body

    reply = json.loads(asyncio.run(fetch()))
    defaults = {name: spec.get("default") for name, spec in reply["schema"]["properties"].items()}
    return {**defaults, **reply["settings"]}


@pytest.mark.parametrize("moved_back", [False, True], ids=["installed", "moved-back"])
def test_the_execution_indicator_is_in_the_status_bar_unless_moved_back(tmp_path, moved_back):
    """In the notebook's toolbar, each change of the execution indicator (two per slider step)
    made the toolbar reset every button's tabindex (``tests/test_browser.py`` watches the
    toolbar during a drag); the package shows it in the status bar, and the user's own
    settings (the Settings Editor writes them) put it back."""
    workdir = tmp_path / "w"
    if moved_back:
        mine = workdir / "settings" / "@jupyterlab" / "notebook-extension"
        mine.mkdir(parents=True)
        back = {"kernelStatus": {"showOnStatusBar": False, "showProgress": True}}
        (mine / "tracker.jupyterlab-settings").write_text(json.dumps(back))
    with server("lab", workdir) as base:
        status = _settings(base, "@jupyterlab/notebook-extension:tracker")["kernelStatus"]
    assert status["showOnStatusBar"] is not moved_back
    assert status["showProgress"] is True
