"""The shipped campaign: every map passes the checker and is won by its input script."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from game.levels import FIRST_LEVEL, LEVELS_DIR, load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import InputScript
from game.sim.tilegrid import TileKind
from tests.maps import write_tmx

SCRIPTS = Path(__file__).resolve().parent / "scripts"
SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))


def test_the_campaign_has_at_least_two_levels_chained_from_the_first() -> None:
    assert len(SHIPPED) >= 2
    chain = [FIRST_LEVEL]
    while (following := load_level(chain[-1]).next_level) is not None:
        chain.append(following)
        assert len(chain) <= len(SHIPPED), "next_level goes round in a loop"
    assert sorted(p.resolve() for p in chain) == [p.resolve() for p in SHIPPED]


def test_the_checker_passes_every_shipped_level() -> None:
    result = subprocess.run([sys.executable, "-m", "game.levels", "check", *map(str, SHIPPED)],
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout == ""


def test_the_checker_names_the_file_and_the_fix_for_a_bad_map(tmp_path: Path) -> None:
    level = write_tmx(tmp_path, ["      ", "  C   ", "######"])      # no Player
    result = subprocess.run([sys.executable, "-m", "game.levels", "check", str(level)],
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 1
    assert result.stdout.startswith(f"{level}: ") and "Player" in result.stdout
    assert " — " in result.stdout and "Traceback" not in result.stdout + result.stderr


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_the_scripted_run_reaches_the_exit(level: Path) -> None:
    script = InputScript.load(SCRIPTS / f"{level.stem}.txt")
    campaign = Campaign(level, loader=load_level)
    while campaign.levels_completed == 0 and campaign.outcome is Outcome.RUNNING:
        campaign.tick(script.held_at(campaign.ticks))
        assert campaign.ticks < 60 * 60, "the script did not reach the exit in a minute"
    assert campaign.levels_completed == 1 and campaign.deaths == 0
    assert campaign.max_penetration_px == 0.0


def test_tile_layers_keep_tiled_document_order_around_object_layers() -> None:
    level = load_level(FIRST_LEVEL)
    assert [layer.name for layer in level.layers] == ["decor", "ground"]
    assert level.foreground == ()


def test_hazard_tiles_use_their_partial_collision_rectangle() -> None:
    path = LEVELS_DIR / "02-over-the-gaps.tmx"
    spikes = [s for s in load_level(path).grid.shapes() if s.kind is TileKind.HAZARD]
    assert spikes
    for shape in spikes:
        assert shape.box.h == 8 and shape.box.w == 14           # drawn in Tiled: (1, 8) 14x8
        assert shape.box.x == shape.col * 16 + 1 and shape.box.y == shape.row * 16 + 8


def test_the_whole_campaign_is_won_from_the_first_level_to_the_win() -> None:
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    start_tick, script = 0, InputScript.load(SCRIPTS / f"{FIRST_LEVEL.stem}.txt")
    level = campaign.world.level.path
    while campaign.outcome is Outcome.RUNNING:
        campaign.tick(script.held_at(campaign.ticks - start_tick))
        if campaign.world.level.path != level:       # on to the next level and its script
            level, start_tick = campaign.world.level.path, campaign.ticks
            script = InputScript.load(SCRIPTS / f"{level.stem}.txt")
        assert campaign.ticks < 60 * 60 * 5
    assert campaign.outcome is Outcome.WON
    assert campaign.levels_completed == len(SHIPPED) and campaign.deaths == 0
