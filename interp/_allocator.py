"""Let the C allocator keep freed memory, so numpy's large temporaries are recycled.

By default glibc hands every freed block over 128 KiB back to the operating system, and the
next array of that size page-faults its way back in. For an image pipeline that allocates the
same dozen 1-8 MiB arrays on every slider step, that is about half the time. Raising the mmap
and trim thresholds keeps those blocks in the process instead. It changes the allocator for
the whole process, so the library never does it on import; the live apps and the benchmark
opt in by calling :func:`keep_freed_memory`.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import sys
from functools import cache

_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3
#: glibc's largest allowed mmap threshold on 64-bit systems.
_MMAP_THRESHOLD_MAX = 32 * 1024 * 1024
_TRIM_THRESHOLD = 512 * 1024 * 1024


@cache
def keep_freed_memory() -> bool:
    """Ask glibc to keep blocks up to 32 MiB for reuse. True if it agreed (Linux only).

    Examples
    --------
    glibc accepts both settings; with any other C library (macOS, musl) the answer is False:

    >>> import platform
    >>> keep_freed_memory() == (platform.libc_ver()[0] == "glibc")
    True
    """
    if not sys.platform.startswith("linux"):
        return False
    name = ctypes.util.find_library("c")
    if name is None:  # pragma: no cover - musl or unusual systems
        return False
    try:
        libc = ctypes.CDLL(name)
        mallopt = libc.mallopt
    except (OSError, AttributeError):  # pragma: no cover
        return False
    mallopt.argtypes = [ctypes.c_int, ctypes.c_int]
    mallopt.restype = ctypes.c_int
    return bool(
        mallopt(_M_MMAP_THRESHOLD, _MMAP_THRESHOLD_MAX)
        and mallopt(_M_TRIM_THRESHOLD, _TRIM_THRESHOLD)
    )
