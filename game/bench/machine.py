"""What the numbers were measured on: the footnote every chart carries.

Where it sits: read once per run by :mod:`game.bench.run` and printed under every chart.

What it teaches: a timing without its machine is not a result. The same bench on a laptop
and a server can differ tenfold, and pygame's C code differs between versions, so every
chart names the CPU, the core count, the operating system, and the Python and pygame (SDL)
versions that produced it. Ratios measured side by side travel between machines far better
than absolute times do.

>>> "Python" in footnote() and "pygame" in footnote()
True
"""

from __future__ import annotations

import os
import platform
from pathlib import Path

import pygame

from game.app.files import FileProblem, read_small_text

MAX_CPUINFO_BYTES = 4 * 1024 * 1024  # /proc/cpuinfo: about 1 kB a core


def cpu_name() -> str:
    """The CPU's model name where the system says it (Linux, macOS), else the architecture."""
    cpuinfo = Path("/proc/cpuinfo")
    if cpuinfo.exists():
        try:
            text = read_small_text(cpuinfo, MAX_CPUINFO_BYTES, "the CPU's description")
        except FileProblem:
            text = ""
        for line in text.splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return platform.processor() or platform.machine() or "unknown CPU"


def footnote() -> str:
    """One line: machine, Python and pygame versions."""
    sdl = ".".join(str(part) for part in pygame.get_sdl_version())
    return (f"{cpu_name()}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"
            f" · {platform.python_implementation()} {platform.python_version()}"
            f" · pygame {pygame.version.ver} (SDL {sdl})")
