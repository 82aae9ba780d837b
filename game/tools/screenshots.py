"""``python -m game.tools.screenshots``: remake the README's pictures from the game itself.

Where it sits: beside the game, not in it. Each picture is one scripted headless run of a
shipped level, stopped at a chosen tick and saved with ``--screenshot`` (and ``--debug``
where the picture shows the overlay), exactly as a reader could run it by hand: the command
for each is printed as it goes. The pictures land in ``assets/screenshots/``.
"""

from __future__ import annotations

import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHOTS = ROOT / "assets" / "screenshots"


@dataclass(frozen=True)
class Shot:
    """One picture: which level, how far into its winning script (or with no input at all,
    for a showcase map that has none), overlay or not."""

    name: str
    level: str
    ticks: int
    debug: bool
    scripted: bool = True

    def command(self) -> list[str]:
        stem = Path(self.level).stem
        inputs = ["--inputs", f"tests/scripts/{stem}.txt"] if self.scripted else []
        args = [sys.executable, "-m", "game", "--headless", "--level", self.level, *inputs,
                "--ticks", str(self.ticks), "--screenshot", f"assets/screenshots/{self.name}.png"]
        return [*args, "--debug"] if self.debug else args


SHOTS_TO_TAKE = (
    Shot("first-steps", "levels/01-first-steps.tmx", 400, debug=False),
    Shot("debug-overlay", "levels/01-first-steps.tmx", 200, debug=True),
    Shot("debug-stomp", "levels/01-first-steps.tmx", 312, debug=True),
    Shot("moving-parts", "levels/04-moving-parts.tmx", 1157, debug=True),
    Shot("debug-fast-fall", "levels/showcase/fast-fall.tmx", 1, debug=True, scripted=False),
)


def main() -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    for shot in SHOTS_TO_TAKE:
        command = shot.command()
        print(" ".join(["python", *command[1:]]))
        subprocess.run(command, cwd=ROOT, check=True)


if __name__ == "__main__":
    main()
