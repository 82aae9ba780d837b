"""``python -m game.tools.lab_screenshots``: remake the README's picture of every lab scene.

Where it sits: beside the game, like :mod:`game.tools.screenshots`. It asks the lab for its
scenes (``python -m game.lab --list``, a name first on each line) and then runs, for each,
the very command a reader could type,
``python -m game.lab --scene NAME --frames N --screenshot PNG``, printing it as it goes.
Every scene runs long enough to fill its timing window (the medians, spreads and history
graphs of :data:`DEFAULT_FRAMES` frames are whole); a scene that only shows something after
more time has passed (a flight reaching its wall, a contact log filling up) gets more frames.
The pictures land in ``assets/screenshots/lab/``. The lab is run as a program, never
imported, so the tools and the lab stay apart.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from game.levels.closed_output import quiet_when_output_closes

ROOT = Path(__file__).resolve().parents[2]
SHOTS = Path("assets") / "screenshots" / "lab"
DEFAULT_FRAMES = 121  # the first frame, then a whole timing window (``game.lab.cost.WINDOW``)
FRAMES = {"tunnelling": 390, "contacts": 420}  # ticks for something to happen


def command(name: str) -> list[str]:
    """The command that draws one scene's picture, as a reader would run it."""
    frames = FRAMES.get(name, DEFAULT_FRAMES)
    return [sys.executable, "-m", "game.lab", "--scene", name, "--frames", str(frames),
            "--screenshot", str(SHOTS / f"{name}.png")]


def main() -> None:
    listed = subprocess.run([sys.executable, "-m", "game.lab", "--list"], cwd=ROOT, check=True,
                            capture_output=True, text=True)
    (ROOT / SHOTS).mkdir(parents=True, exist_ok=True)
    for name in (line.split()[0] for line in listed.stdout.splitlines() if line.strip()):
        args = command(name)
        print(" ".join(["python", *args[1:]]))
        subprocess.run(args, cwd=ROOT, check=True)


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
