"""A Jupyter server extension: kernel messages leave for the page at once.

The Jupyter server relays each kernel message to the page over a websocket, and leaves
Nagle's algorithm on for that socket (jupyter_server 2.21 never calls ``set_nodelay``). With
it on, the operating system holds a message back while an earlier one is still unacknowledged,
and a page that has just sent something acknowledges late (Linux delays an acknowledgement by
up to 40 ms). A slider step makes the kernel send a few small messages at once (busy, the
slider's echo, idle) and the new picture 20-40 ms later. Traced in JupyterLab and Chromium
(lesson 1's app, 15 steps each, a cell run just before each step): the picture reached the page
15-17 ms after the kernel sent it, and 1.5 ms after with ``TCP_NODELAY``; from the key press to
new pixels, 60 ms became 43 ms. For slider steps alone (no cell run in between) the picture
took 2-3 ms either way, and ``make bench-browser`` shows no difference beyond its noise.

Installing the package enables this extension for JupyterLab and ``jupyter server`` (the file
``etc/jupyter/jupyter_server_config.d/interp.server.json`` in the environment);
``python -m interp.classroom`` applies it to Voilà's own server. To turn it off:
``jupyter server extension disable interp.server``.
"""

from __future__ import annotations

import functools

from jupyter_server.services.kernels.websocket import KernelWebsocketHandler


def send_at_once() -> None:
    """Make every kernel websocket the server opens from now on send without delay
    (``TCP_NODELAY``); Voilà's handler is a subclass of jupyter_server's, so it too.

    Examples
    --------
    >>> send_at_once()
    >>> KernelWebsocketHandler.open.sends_at_once
    True
    """
    opened = KernelWebsocketHandler.open
    if getattr(opened, "sends_at_once", False):
        return

    @functools.wraps(opened)
    async def open_sending_at_once(self: KernelWebsocketHandler, *args: object, **kw: object):
        self.set_nodelay(True)
        return await opened(self, *args, **kw)

    open_sending_at_once.sends_at_once = True  # type: ignore[attr-defined]
    KernelWebsocketHandler.open = open_sending_at_once


def _jupyter_server_extension_points() -> list[dict[str, str]]:
    """Where Jupyter finds this extension."""
    return [{"module": "interp.server"}]


def _load_jupyter_server_extension(serverapp: object) -> None:
    """Called by the Jupyter server when it starts."""
    send_at_once()
    serverapp.log.info("interp.server: kernel messages are sent to the page at once (TCP_NODELAY)")
