"""Open a window only where someone can see it: the display check of the game and the lab.

Where it sits: at the start of ``python -m game`` and ``python -m game.lab`` when they are
about to open a window, before pygame's display starts; :mod:`game.app.run` and
:mod:`game.lab.cli` call it. Headless runs (``--headless``, the lab's ``--screenshot``) choose
SDL's ``dummy`` driver themselves and never come here.

What it teaches: with no display, SDL does not fail; it falls back to an ``offscreen``
driver, and a program would run on, drawing frames nobody sees. So the check looks first at
the environment (on Linux and the BSDs a window needs ``DISPLAY`` for X11 or
``WAYLAND_DISPLAY`` for Wayland) and then at the driver SDL picked, and says in one
sentence what to run instead. ``SDL_VIDEODRIVER`` set by hand is a choice, respected: tests
run the window loop with ``SDL_VIDEODRIVER=dummy``.

It also names the window before SDL makes it: the title, and the class that a taskbar or a
window manager's rules go by (``WM_CLASS`` on X11, the app id on Wayland), which SDL 2 reads
from ``SDL_VIDEO_X11_WMCLASS`` and ``SDL_VIDEO_WAYLAND_WMCLASS`` when the display starts.
Without them pygame names the window after ``sys.argv[0]``: ``__main__.py``.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping, MutableMapping

GAME_WINDOW = "tile-hopper"  # the game window's title and class
LAB_WINDOW = "tile-hopper lab"  # the lab's
GAME_INSTEAD = ("run with --headless to play without one "
                "(add --screenshot FILE to save the last frame as PNG)")
LAB_INSTEAD = ("use --screenshot PNG to draw a scene without one "
               "(with --scene NAME and --frames N), or --list to list the scenes")
EXIT_NO_WINDOW = 1  # the exit status of a program that cannot show its window
CLASS_VARIABLES = ("SDL_VIDEO_X11_WMCLASS", "SDL_VIDEO_WAYLAND_WMCLASS", "SDL_APP_NAME")
UNSEEN_DRIVERS = ("offscreen", "dummy")  # SDL drivers that draw where nobody can see
DISPLAY_PLATFORMS = ("linux", "freebsd", "openbsd", "netbsd", "dragonfly")  # X11 or Wayland


def missing_display(environ: Mapping[str, str] = os.environ,
                    platform: str = sys.platform) -> str | None:
    """Why no window can be seen here, read from the environment alone (quick enough to
    ask before pygame is even imported); None if one might.

    >>> missing_display({}, "linux")
    'neither DISPLAY nor WAYLAND_DISPLAY is set'
    >>> missing_display({"DISPLAY": ":0"}, "linux") is None
    True
    >>> missing_display({"SDL_VIDEODRIVER": "dummy"}, "linux") is None  # chosen by hand
    True
    >>> missing_display({}, "darwin") is None  # macOS and Windows always have a desktop
    True
    """
    if environ.get("SDL_VIDEODRIVER"):
        return None
    if not platform.startswith(DISPLAY_PLATFORMS):
        return None
    if environ.get("DISPLAY") or environ.get("WAYLAND_DISPLAY"):
        return None
    return "neither DISPLAY nor WAYLAND_DISPLAY is set"


def name_window(name: str, environ: MutableMapping[str, str] = os.environ) -> None:
    """Give the window SDL is about to make the class ``name`` (call before the display
    starts; the title is set after, with ``pygame.display.set_caption``).

    >>> names: dict[str, str] = {}
    >>> name_window("tile-hopper", names)
    >>> sorted(set(names.values()))
    ['tile-hopper']
    """
    for variable in CLASS_VARIABLES:
        environ[variable] = name


def no_window(program: str, why: str, instead: str) -> str:
    """The one sentence a program ends with when it cannot show its window.

    >>> no_window("python -m game", "no display", "run with --headless")
    'python -m game: cannot open a window (no display); run with --headless.'
    """
    return f"{program}: cannot open a window ({why}); {instead}."


def open_window(program: str, name: str, size: tuple[int, int], instead: str) -> str | None:
    """Open a scaled, resizable window called ``name`` (title and class) of ``size``
    pixels: None when it is open and can be seen, else the sentence to end with
    (``instead`` says what to run without a window).

    With ``DISPLAY`` set and ``WAYLAND_DISPLAY`` not, SDL is asked for X11 alone, so an X
    server that does not answer is an error here rather than a Wayland probe (which prints
    its own line about ``XDG_RUNTIME_DIR``) and a fall back to the offscreen driver."""
    if (why := missing_display()) is not None:
        return no_window(program, why, instead)
    chosen = bool(os.environ.get("SDL_VIDEODRIVER"))
    if not chosen and os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        os.environ["SDL_VIDEODRIVER"] = "x11"
    name_window(name)
    import pygame  # here, so that a missing display is said before pygame is loaded

    try:
        pygame.display.init()
        if not chosen and (driver := pygame.display.get_driver()) in UNSEEN_DRIVERS:
            pygame.display.quit()
            return no_window(program, f"SDL found no display, only its {driver} driver",
                             instead)
        pygame.display.set_mode(size, pygame.SCALED | pygame.RESIZABLE)
    except pygame.error as error:
        return no_window(program, f"{error}; DISPLAY is {os.environ.get('DISPLAY', '')!r}",
                         instead)
    pygame.display.set_caption(name)
    return None
