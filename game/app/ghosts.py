"""The ghost: the player's best run of a level, replayed beside them, see-through.

Where it sits: in the app, beside the progress (:mod:`game.app.saves`). When a finish sets
a level's best time (and no assist was on), the window saves the inputs of that run in
``ghosts/LEVEL.json`` in the data folder, with a hash of the map file it was played on. When
the level starts again with the ghost on (the options' Ghost row), :func:`load_replay` reads
it back and :class:`Replay` plays those inputs in a second :class:`~game.sim.world.World`,
one tick for each tick of play; :func:`draw_ghost` draws its player translucent.

What it teaches:
  * **A deterministic simulation replays from its inputs.** The same map, the same tuning
    and the same held actions on the same ticks give the same positions, so a run is kept
    as a few hundred input changes (an input script, :mod:`game.sim.inputs`), not as
    thousands of positions.
  * **A replay is only as good as the map it was made on.** Change a wall and the same
    inputs go somewhere else: the ghost keeps the SHA-256 of the map file, and a map whose
    hash differs, or that cannot be read, shows no ghost rather than a wrong one.
  * **The player's files are read and written with the same care as the others**: through
    :class:`game.app.saves.JsonFile` (bounded read, atomic write, a bad file kept aside).

>>> ghost, problems = Ghost.from_json({"version": 1, "map_sha256": "ab", "ticks": 3,
...                                    "inputs": "0 +right\\n"})
>>> ghost.ticks, problems
(3, [])
>>> Ghost.from_json({"ticks": -1})[1]  # doctest: +NORMALIZE_WHITESPACE
['map_sha256 is missing or not text', 'ticks is -1, not a whole number from 1 to 1,000,000,000,000',
 'inputs is missing or not text']
"""

from __future__ import annotations

import functools
import hashlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pygame

from game.app.assets import Assets
from game.app.files import FileProblem, read_small_bytes
from game.app.render import screen_offset
from game.app.saves import MAX_COUNT, JsonFile, data_dir, quoted
from game.levels.tiledxml import MAX_FILE_BYTES
from game.sim.camera import Camera
from game.sim.inputs import InputScript, InputScriptError, Recorder
from game.sim.level import Level
from game.sim.tuning import Tuning
from game.sim.world import World

GHOSTS_DIR = "ghosts"  # beside settings.json and progress.json
GHOST_VERSION = 1  # written into each file; bump it if its layout ever changes
GHOST_ALPHA = 110  # 0..255: how solid the ghost is drawn
GHOST_NAME = "the ghost"  # how an input script error names a ghost's inputs


@dataclass(frozen=True)
class Ghost:
    """A best run of one level: the map it was played on, its length and its inputs."""

    map_sha256: str
    ticks: int  # the run's length: its last tick is the one that reached the exit
    inputs: str  # an input script (game.sim.inputs), its ticks counted from the level's start

    def to_json(self) -> dict[str, Any]:
        return {"version": GHOST_VERSION, "map_sha256": self.map_sha256, "ticks": self.ticks,
                "inputs": self.inputs}

    @classmethod
    def from_json(cls, data: Any) -> tuple[Ghost | None, list[str]]:
        """A ghost from decoded JSON, or None and what is wrong with it."""
        if not isinstance(data, dict):
            return None, ["it does not hold a JSON object"]
        problems = []
        sha, ticks, inputs = data.get("map_sha256"), data.get("ticks"), data.get("inputs")
        if not isinstance(sha, str):
            problems.append("map_sha256 is missing or not text")
        if (not isinstance(ticks, int) or isinstance(ticks, bool)
                or not 1 <= ticks <= MAX_COUNT):
            problems.append(f"ticks is {quoted(ticks)}, not a whole number from 1 to "
                            f"{MAX_COUNT:,}")
        if not isinstance(inputs, str):
            problems.append("inputs is missing or not text")
        else:
            try:
                InputScript.parse(inputs, GHOST_NAME)
            except InputScriptError as error:
                problems.append(f"inputs: {error}")
        if problems:
            return None, problems
        assert isinstance(sha, str) and isinstance(ticks, int) and isinstance(inputs, str)
        return cls(sha, ticks, inputs), []


def map_hash(path: Path) -> str | None:
    """The SHA-256 of the map file, read through the bounded read; None if it cannot be read."""
    try:
        return hashlib.sha256(read_small_bytes(path, MAX_FILE_BYTES, "the map")).hexdigest()
    except FileProblem:
        return None


def ghost_file(level_name: str, directory: Path | None = None) -> JsonFile:
    """The ghost of the level whose map file is called ``level_name``."""
    return JsonFile((directory or data_dir()) / GHOSTS_DIR / f"{Path(level_name).name}.json")


def recorded(recorder: Recorder, ticks: int, map_path: Path) -> Ghost | None:
    """The ghost of a run whose inputs ``recorder`` kept, or None if the map cannot be read."""
    sha = map_hash(map_path)
    return None if sha is None else Ghost(sha, ticks, recorder.text())


def save_ghost(ghost: Ghost, level_name: str, directory: Path | None = None) -> str | None:
    """Write the ghost of a level; a sentence if it could not be saved."""
    return ghost_file(level_name, directory).save(ghost.to_json())


class Replay:
    """A ghost's run played again in its own world, one tick at a time."""

    def __init__(self, ghost: Ghost, level: Level, tuning: Tuning) -> None:
        self.world = World(level, tuning)
        self.script = InputScript.parse(ghost.inputs, GHOST_NAME)
        self.ticks = ghost.ticks
        self.tick = 0  # ticks replayed so far

    @property
    def done(self) -> bool:
        """The ghost has reached the exit: it is no longer drawn."""
        return self.tick >= self.ticks

    def step(self) -> None:
        """Replay one more tick (nothing once the run is over)."""
        if not self.done:
            self.world.step(self.script.held_at(self.tick))
            self.tick += 1


def load_replay(level: Level, tuning: Tuning, directory: Path | None = None
                ) -> tuple[Replay | None, str | None]:
    """The replay of ``level``'s ghost, if it has one made on this very map; and a sentence
    when its file could not be used (it is then kept aside, as a bad progress file is)."""
    file = ghost_file(level.path.name, directory)
    if not file.path.exists():
        return None, None
    ghost, problem = file.load(Ghost.from_json, lambda: None)
    if ghost is None or ghost.map_sha256 != map_hash(level.path):
        return None, problem
    return Replay(ghost, level, tuning), problem


@functools.lru_cache(maxsize=4)
def _see_through(picture: pygame.Surface, flipped: bool) -> pygame.Surface:
    """The ghost's picture: the player's, turned round when ``flipped``, at GHOST_ALPHA;
    made once for each way it faces, not every frame."""
    seen = pygame.transform.flip(picture, True, False) if flipped else picture.copy()
    seen.set_alpha(GHOST_ALPHA)
    return seen


def draw_ghost(target: pygame.Surface, assets: Assets, replay: Replay, camera: Camera) -> None:
    """The ghost's player, see-through, where its run has it now (through the play camera)."""
    if replay.done:
        return
    player = replay.world.player
    picture = _see_through(assets.player_frames[0], player.facing < 0)
    x, y = screen_offset(camera)
    box = player.box
    target.blit(picture, picture.get_rect(midbottom=(round(box.x + box.w / 2) - x,
                                                     round(box.bottom) - y)))
