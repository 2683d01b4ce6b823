"""The server extension ``interp.server``: a real JupyterLab server, installed as ``make`` installs
it, sends kernel messages over a websocket with ``TCP_NODELAY`` set.

The option is read from the server's own socket (Linux: ``pidfd_getfd`` copies the socket into
this process), for the connection a websocket client opened to a kernel, as JupyterLab's page
does. With the extension turned off the same socket has Nagle's algorithm on: tornado's
default, the cause of 15-40 ms of waiting per picture that ``interp.server`` describes.
"""

from __future__ import annotations

import asyncio
import json
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
