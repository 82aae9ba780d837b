"""The shipped campaign played once, from the first level to the last, by the winning
scripts in ``tests/scripts``: each level by its own script from the tick it starts. What
the run showed of each level is kept for every test that asks (``tests/test_levels.py``
checks the ticks it is won at, ``tests/test_places.py`` the camera over its pits), so the
campaign is played once however many of them run."""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from pathlib import Path

from game.app.render import floor_line_px
from game.app.run import input_script
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign, Outcome
from tests.maps import MEASURED

SCRIPTS = Path(__file__).resolve().parent / "scripts"
MAX_LEVEL_TICKS = 60 * 60 * 5  # a script that has not won its level in 5 minutes never will


def pit_columns(grid: TileGrid) -> list[int]:
    """The columns with no solid ground at the floor line: the level's pits."""
    floor = floor_line_px(grid) // grid.tile_h
    return [col for col in range(grid.cols)
            if not any(s.kind is TileKind.SOLID for s in grid.shapes_at(col, floor))]


@dataclass
class LevelPlayed:
    """What the campaign's run showed of one level, played by its script."""

    won_at: int | None = None  # the script's tick on which the level was completed
    deaths: int = 0  # the campaign's deaths when it was completed
    pit_views: int = 0  # ticks whose view showed a pit (tests/test_places.py)
    pit_bottom_hidden: list[str] = field(default_factory=list)  # ...without its bottom


@dataclass
class CampaignPlayed:
    """The whole campaign played once by the winning scripts, one after the other."""

    outcome: Outcome
    max_penetration_px: float
    levels: dict[str, LevelPlayed]


@functools.cache  # one play of the campaign serves every test that watches it
def campaign_played() -> CampaignPlayed:
    """Play the campaign from the first level, each level by its own script from the tick
    it starts; after every tick, note whether the view shows a pit of the level in play
    and, if so, whether it shows the map's bottom too."""
    campaign = Campaign(FIRST_LEVEL, loader=load_level, measure=MEASURED)
    start_tick, script = 0, input_script(SCRIPTS / f"{FIRST_LEVEL.stem}.txt")
    level = campaign.world.level.path
    levels = {level.stem: LevelPlayed()}
    pits = pit_columns(campaign.world.level.grid)
    while campaign.outcome is Outcome.RUNNING:
        campaign.tick(script.held_at(campaign.ticks - start_tick))
        played = levels[level.stem]
        if campaign.levels_completed > sum(p.won_at is not None for p in levels.values()):
            played.won_at, played.deaths = campaign.ticks - start_tick, campaign.deaths
            if campaign.outcome is not Outcome.RUNNING:
                break
            level, start_tick = campaign.world.level.path, campaign.ticks  # the next level
            script = input_script(SCRIPTS / f"{level.stem}.txt")
            played = levels[level.stem] = LevelPlayed()
            pits = pit_columns(campaign.world.level.grid)
        if campaign.ticks - start_tick >= MAX_LEVEL_TICKS:
            break  # no exit in 5 minutes: the test says so
        grid, camera = campaign.world.level.grid, campaign.world.camera
        left, right = camera.x, camera.x + camera.view_w
        seen = [col for col in pits
                if left < (col + 1) * grid.tile_w and col * grid.tile_w < right]
        if seen:
            played.pit_views += 1
            if camera.y + camera.view_h < grid.rows * grid.tile_h:
                played.pit_bottom_hidden.append(
                    f"tick {campaign.ticks - start_tick}: pit at column {seen[0]} in view, "
                    "its bottom is not")
    return CampaignPlayed(campaign.outcome, campaign.max_penetration_px, levels)
