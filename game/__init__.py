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
import importlib.util
import os
import sys
from types import ModuleType

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


def _lazily(package_folder: str, name: str) -> ModuleType | None:
    """``pygame.<name>``, ready to load on its first use (:class:`importlib.util.LazyLoader`)."""
    path = os.path.join(package_folder, f"{name}.py")
    spec = importlib.util.spec_from_file_location(f"pygame.{name}", path)
    if spec is None or spec.loader is None or not os.path.isfile(path):
        return None
    spec.loader = importlib.util.LazyLoader(spec.loader)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)  # lazily: the module's own code runs on first use
    return module


def _import_pygame() -> None:
    """Import pygame without setuptools' ``pkg_resources``, and without numpy until asked.

    pygame looks up its own files (the default font, the window icon) through
    ``pkg_resources`` when that imports, which costs about a fifth of a second at every start,
    and otherwise in its own package folder, as on a Python without setuptools (3.12 and
    later). The game takes the second way: ``pkg_resources`` is kept out while pygame is
    imported, and only then.

    pygame also imports ``surfarray`` and ``sndarray``, and through them numpy when it is
    installed (the benchmark's charts need it): about a sixth of a second more. The game uses
    neither, so numpy is kept out the same way, and both modules are put back ready to load,
    numpy with them, the first time they are used.
    """
    if "pygame" in sys.modules or "pkg_resources" in sys.modules:
        return
    kept_out = ["pkg_resources"]
    if "numpy" not in sys.modules and importlib.util.find_spec("numpy") is not None:
        kept_out.append("numpy")
    for name in kept_out:
        sys.modules[name] = None  # type: ignore[assignment]  # importing it now fails
    try:
        import pygame
    finally:
        for name in kept_out:
            del sys.modules[name]
    if "numpy" in kept_out and pygame.__file__ is not None:
        for name in ("surfarray", "sndarray"):
            module = _lazily(os.path.dirname(pygame.__file__), name)
            if module is not None:  # (touching any of its names would load it)
                sys.modules[f"pygame.{name}"] = module
                setattr(pygame, name, module)


_import_pygame()
