"""``python -m game.lab [--list] [--scene NAME] [--screenshot PNG] [--frames N]``.

Where it sits: the entry point of the lab. With no option it opens a window with the list
of scenes; ``--scene NAME`` opens that scene; ``--list`` prints the scene names, one a line
(on a terminal, or with ``--long``, each name is followed by its group and what it shows);
``--screenshot PNG`` runs ``--frames`` frames (default 1) without any window and saves a
picture of the last one. Exit status: 0 done, 1 the picture could not be saved or no
display for the window (one sentence naming ``--screenshot`` and ``--list``), 2 bad usage
(an unknown scene name prints the list on stderr).

What it teaches: a headless mode is the same loop with the window taken away. The
screenshot runs the very frames a window would, with ``SDL_VIDEODRIVER=dummy``, so a test or
a README picture sees what a reader sees.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from game.app.arguments import Parser, excerpt, whole_number
from game.app.display import EXIT_NO_WINDOW, LAB_INSTEAD, LAB_WINDOW, open_window
from game.app.files import FileProblem, output_problem, save_image, shown
from game.lab.catalogue import SCENES
from game.levels.closed_output import say

MAX_FRAMES = 36_000  # ten minutes of the lab at 60 frames a second

WINDOW_FPS = 60


def scene_names() -> list[str]:
    return [scene.name for scene in SCENES]


def listing() -> list[str]:
    """``--list --long``: each scene's name, group and title, in columns, in the list's order."""
    name_w = max(len(scene.name) for scene in SCENES)
    group_w = max(len(scene.group) for scene in SCENES)
    return [f"{scene.name:<{name_w}}  {scene.group:<{group_w}}  {scene.title}"
            for scene in SCENES]


def main(argv: list[str] | None = None) -> int:
    parser = Parser(
        prog="python -m game.lab",
        description="Interactive scenes, one per collision technique.")
    parser.add_argument("--list", action="store_true",
                        help="print the scene names, one a line, and exit (on a terminal, "
                             "each with its group and description, as with --long)")
    parser.add_argument("--long", action="store_true",
                        help="with --list: each name with its group and description, always")
    parser.add_argument("--scene", metavar="NAME", help="open this scene")
    parser.add_argument("--screenshot", metavar="PNG", type=Path,
                        help="draw without a window and save the last frame here")
    parser.add_argument("--frames", metavar="N", default=1,
                        type=whole_number(1, MAX_FRAMES, "frames"),
                        help="frames to run; the screenshot shows the last (default 1)")
    args = parser.parse_args(argv)
    names = scene_names()
    if args.list:
        # Bare names when a script reads them (the public form), columns for a person.
        # An output closed or full (| head -1) ends the listing quietly, still status 0.
        say("\n".join(listing() if args.long or (sys.stdout is not None
                                                 and sys.stdout.isatty()) else names))
        return 0
    if args.scene is not None and args.scene not in names:
        print(f"python -m game.lab: there is no scene called {excerpt(args.scene)}; the scenes "
              "are:",
              file=sys.stderr)
        print("\n".join(names), file=sys.stderr)
        return 2
    if args.frames < 1:
        parser.error(f"--frames must be 1 or more, not {args.frames}")
    if args.screenshot is not None and (problem := output_problem(args.screenshot)):
        print(f"python -m game.lab: --screenshot: {problem}", file=sys.stderr)
        return 1  # like the game: a file that cannot be written
    if args.screenshot is not None:
        return screenshot(args.scene, args.screenshot, args.frames)
    return window(args.scene)


def _start_pygame(headless: bool) -> None:
    """Fonts always; the display only when headless (a window opens through
    :func:`game.app.display.open_window`, which checks first that it can be seen)."""
    if headless:
        os.environ["SDL_VIDEODRIVER"] = "dummy"
    os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    import pygame

    if headless:
        pygame.display.init()
    pygame.font.init()


def screenshot(scene: str | None, path: Path, frames: int) -> int:
    """Run ``frames`` frames of ``scene`` (or the list) headless; save the last as PNG.

    Only the last frame is drawn: drawing reads the scene and changes none of it, so the
    frames before it would only be painted over."""
    _start_pygame(headless=True)
    import pygame

    from game.lab.testbed import Lab, screen

    pygame.display.set_mode((1, 1))  # images can be converted; nothing is shown
    bed = Lab(SCENES, start=scene)
    surface = screen()
    for _ in range(frames):
        bed.frame()
    bed.draw(surface)
    if not path.parent.is_dir():
        print(f"python -m game.lab: cannot save the screenshot {shown(path)}: its folder does "
              "not exist", file=sys.stderr)
        return 1
    try:
        save_image(surface, path)
    except FileProblem as error:
        print(f"python -m game.lab: cannot save the screenshot: {error}", file=sys.stderr)
        return 1
    return 0


def window(scene: str | None) -> int:
    """The interactive lab: a window until it is closed, or Esc in the list."""
    _start_pygame(headless=False)
    import pygame

    from game.lab.scene import LAB_H_PX, LAB_W_PX
    from game.lab.testbed import Lab, fit_window

    problem = open_window("python -m game.lab", LAB_WINDOW, (LAB_W_PX, LAB_H_PX), LAB_INSTEAD)
    if problem is not None:
        print(problem, file=sys.stderr)
        return EXIT_NO_WINDOW
    display = pygame.display.get_surface()
    window = fit_window()  # held while the window is open (see game.app.window.fit_window)
    bed = Lab(SCENES, start=scene)
    clock = pygame.time.Clock()
    while bed.running:
        bed.frame()
        bed.draw(display)
        pygame.display.flip()
        clock.tick(WINDOW_FPS)
    pygame.display.quit()
    del window  # only now: SDL may hand it to events until the display is gone
    return 0
