"""Tile Hopper: a pygame platformer whose code teaches 2D collision detection.

Start reading at :mod:`game.collision.axis_sweep` (the swept x and y passes) and
:mod:`game.sim.world` (one tick, top to bottom). The README maps every technique to its module.

Ctrl-C while a command is still loading its modules (``python -m game``, ``python -m
game.levels``, ``python -m game.lab``, ``tile-hopper``) ends it with status 130 and one line,
never an import's traceback: :func:`guard_startup` is installed here, the first module any
of them runs, and each command hands Ctrl-C back to Python (a KeyboardInterrupt it catches)
once its modules are loaded.
"""

import _signal  # type: ignore[import-not-found]  # C module: ``signal`` builds enums first
import os
import sys

EXIT_INTERRUPTED = 130  # 128 + SIGINT


def _stopped_while_loading(_signum: int, _frame: object) -> None:
    """Ctrl-C before a command runs: nothing has been written yet, so stop at once."""
    os.write(2, b"stopped by Ctrl-C\n")
    os._exit(EXIT_INTERRUPTED)


def guard_startup() -> None:
    """Make Ctrl-C end the program quietly (status 130) until the command takes it over."""
    try:  # noqa: SIM105 (contextlib is one more import before the guard is up)
        _signal.signal(_signal.SIGINT, _stopped_while_loading)
    except ValueError:  # only the main thread may set a handler
        pass


# ``python -m`` sets argv[0] to "-m" while it imports the packages on the way to __main__.
_ARGV0 = (getattr(sys, "argv", None) or [""])[0]
if _ARGV0 == "-m" or os.path.basename(_ARGV0) == "tile-hopper":
    guard_startup()

# Keep the console for the game's own words.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")


def _import_pygame() -> None:
    """Import pygame without setuptools' ``pkg_resources`` and without numpy.

    pygame looks up its own files (the default font, the window icon) through
    ``pkg_resources`` when that imports, which costs about a fifth of a second at every start,
    and otherwise in its own package folder, as on a Python without setuptools (3.12 and
    later). Wherever numpy is installed, pygame also imports it for ``pygame.surfarray`` and
    ``pygame.sndarray``, which the game never uses: about a sixth of a second more. The game
    takes pygame as it is without either: both are kept out while pygame is imported, and
    only then (the bench imports numpy later, as usual).
    """
    if "pygame" in sys.modules:
        return
    kept_out = [name for name in ("pkg_resources", "numpy") if name not in sys.modules]
    for name in kept_out:
        sys.modules[name] = None  # type: ignore[assignment]  # importing it now fails
    try:
        import pygame  # noqa: F401
    finally:
        for name in kept_out:
            del sys.modules[name]


_import_pygame()
