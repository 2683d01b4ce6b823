"""Serving the lessons to a room: Voilà with kernels that do not pile up.

Voilà starts one kernel per open page and never shuts it down when the tab is closed (the
browser's shutdown request is refused; upstream voila issue #1458). A day of projecting, or a
class opening the app, would leave a kernel for every page ever opened, about 130 MB each. So
``make present`` runs Voilà through :func:`main` here, which

- culls kernels that are idle and have no page connected (a closed tab) after ``--idle``
  seconds, checking every ``--interval`` seconds; a kernel whose page has not connected yet
  (the browser is still loading it: the idle clock starts when the notebook's cells finish)
  is kept for at least ``page_wait`` seconds, so a slow page never finds its kernel gone;
- caps the live kernels at ``--max-kernels``, counting the kernels still starting, so that a
  class opening the page at once cannot pass it: when a new page would pass the cap, the kernel
  idle longest with no page connected is shut down to make room; if every kernel has a page
  open, the new page gets "503: the server is full" at once instead of exhausting the machine.

Usage: ``python -m interp.classroom [--idle S] [--interval S] [--max-kernels N] [PATH]``; other
arguments go to Voilà unchanged.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import time
from collections.abc import Sequence

from jupyter_server.services.kernels.kernelmanager import AsyncMappingKernelManager
from tornado import web
from traitlets import Integer

#: Defaults for a classroom: a closed tab's kernel goes after 5 minutes; at most 30 kernels
#: (about 4 GB) at once.
IDLE_SECONDS, INTERVAL_SECONDS, MAX_KERNELS = 300, 60, 30
#: Seconds a kernel waits for its page to connect before the culler may take it: a page
#: takes a few seconds to load after its cells ran (more on a busy server).
PAGE_WAIT_SECONDS = 60


class ClassroomKernelManager(AsyncMappingKernelManager):
    """Voilà's kernel manager with a cap on live kernels (culling is the parent's)."""

    max_kernels = Integer(
        MAX_KERNELS, config=True, help="Most kernels alive at once; 0 for no limit."
    )
    page_wait = Integer(
        PAGE_WAIT_SECONDS,
        config=True,
        help="Seconds a new kernel is kept, idle or not, until its page connects.",
    )

    def __init__(self, **kwargs: object) -> None:
        super().__init__(**kwargs)
        self._unconnected: dict[str, float] = {}  # kernel id -> when it started
        self._starting = 0  # kernels asked for and not started yet
        self._admitting = asyncio.Lock()  # one page at a time is counted against the cap

    async def start_kernel(self, **kwargs: object) -> str:
        """Start a kernel, first making room if the cap is reached (503 if none can be made)."""
        async with self._admitting:
            if self.max_kernels > 0:
                while len(self.list_kernel_ids()) + self._starting >= self.max_kernels:
                    await self._make_room()
            self._starting += 1
        try:
            kernel_id = await super().start_kernel(**kwargs)
        finally:
            self._starting -= 1
        self._unconnected[kernel_id] = time.monotonic()
        return kernel_id

    def notify_connect(self, kernel_id: str) -> None:
        """Note a page's connection: from now on the kernel is culled as any other."""
        super().notify_connect(kernel_id)
        self._unconnected.pop(kernel_id, None)

    async def cull_kernel_if_idle(self, kernel_id: str) -> None:
        """Cull as Jupyter does, but not a kernel still waiting for its page."""
        started = self._unconnected.get(kernel_id)
        if started is not None and time.monotonic() - started < self.page_wait:
            return
        await super().cull_kernel_if_idle(kernel_id)

    def remove_kernel(self, kernel_id: str) -> object:
        """Forget a kernel (every shutdown ends here, as does a dead kernel's removal)."""
        self._unconnected.pop(kernel_id, None)
        return super().remove_kernel(kernel_id)

    async def _make_room(self) -> None:
        """Shut down the kernel idle longest with no page connected, or refuse the new page
        with a 503."""
        unwatched = [k for k in self.list_kernel_ids() if not self._kernel_connections.get(k)]
        if not unwatched:
            full = f"The server is full ({self.max_kernels} pages are open): close one"
            raise web.HTTPError(503, full, reason=full)
        oldest = min(unwatched, key=lambda k: self.get_kernel(k).last_activity)
        self.log.info("interp: at %d kernels, shutting down idle %s", self.max_kernels, oldest)
        await self.shutdown_kernel(oldest)


def voila_arguments(idle: int, interval: int, max_kernels: int) -> list[str]:
    """The Voilà options that turn culling and the cap on.

    Examples
    --------
    >>> voila_arguments(300, 60, 30)[0]
    '--VoilaConfiguration.multi_kernel_manager_class=interp.classroom.ClassroomKernelManager'
    """
    return [
        "--VoilaConfiguration.multi_kernel_manager_class=interp.classroom.ClassroomKernelManager",
        f"--ClassroomKernelManager.cull_idle_timeout={idle}",
        f"--ClassroomKernelManager.cull_interval={interval}",
        "--ClassroomKernelManager.cull_connected=False",
        f"--ClassroomKernelManager.max_kernels={max_kernels}",
    ]


def main(argv: Sequence[str] | None = None) -> None:
    """Run Voilà with culling and a kernel cap (replaces this process)."""
    parser = argparse.ArgumentParser(
        prog="python -m interp.classroom",
        description="Voilà for a classroom: idle kernels of closed pages are shut down, and "
        "the number of live kernels is capped. Other arguments go to Voilà.",
    )
    parser.add_argument("--idle", type=int, default=IDLE_SECONDS, help="seconds (default 300)")
    parser.add_argument(
        "--interval", type=int, default=INTERVAL_SECONDS, help="seconds (default 60)"
    )
    parser.add_argument("--max-kernels", type=int, default=MAX_KERNELS, help="(default 30)")
    args, voila = parser.parse_known_args(argv)
    for name in ("idle", "interval", "max_kernels"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be at least 1")
    command = [
        sys.executable,
        "-m",
        "voila",
        *voila_arguments(args.idle, args.interval, args.max_kernels),
        *voila,
    ]
    os.execv(sys.executable, command)


if __name__ == "__main__":
    main()
