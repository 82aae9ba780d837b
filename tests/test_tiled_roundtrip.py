"""Through real Tiled and back: every shipped level re-saved by ``tiled --export-map`` still
passes the checker and plays exactly the same.

Three ways of saving: as it is; with the tileset embedded in the map (with its collision
rectangles, which is where pytmx 3.32 invents a layer); and with the object types' defaults
written into every object (``--resolve-types-and-properties``, which needs the project's
``objecttypes.xml`` where Tiled 1.8's command line looks for it). Tiled writes paths
relative to the saved file, so each variant is saved in place in a copy of the project
(the tilesets, the same bytes for every variant, are re-saved once and copied).

"Plays the same" is shown in two steps. Every re-saved level loads to a :class:`Level`
equal, field by field (every collision shape of its grid included), to the one the original
gives, apart from the folder it was read from; a play starts from that value alone and is
deterministic, so it cannot tell the two apart. Then one level in each variant is played
to its exit beside the original, so that the claim is also checked on a real run.

"Passes the checker" is the checker run on the re-saved files (``check --no-solve``). Its
dearest part, the reach fill behind the unreachable-Coin warning, is a function of the loaded
level alone: while the check runs, a re-saved level equal to an original (as above, apart
from its folder) is given the fill worked out once for that original
(:mod:`tests.shipped_fills`); any other would get its own, and none does.
"""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from game.app.run import input_script
from game.checker.cli import main as levels_main
from game.levels import FIRST_LEVEL, LEVELS_DIR, load_level
from game.levels.project import OBJECT_TYPES_FILE
from game.sim.campaign import Campaign, Outcome
from game.sim.level import Level
from tests.in_process import call_main
from tests.shipped_fills import folderless, share_fills

TILED = shutil.which("tiled")
SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))
SCRIPTS = Path(__file__).resolve().parent / "scripts"
VARIANTS = {"resaved": [], "embedded-tilesets": ["--embed-tilesets"],
            "types-resolved": ["--resolve-types-and-properties"]}
MAX_TICKS = 60 * 60

pytestmark = pytest.mark.skipif(TILED is None, reason="Tiled is not installed")


def tiled(*args: str | Path, home: Path) -> None:
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(home),
           "XDG_CONFIG_HOME": str(home / "config"), "XDG_DATA_HOME": str(home / "data"),
           "XDG_RUNTIME_DIR": str(home)}
    result = subprocess.run([str(TILED), *map(str, args)], env=env, capture_output=True,
                            text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.fixture(scope="module")
def resaved(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """For each variant, the folder of a project copy whose levels Tiled saved again."""
    home = tmp_path_factory.mktemp("home")
    home.chmod(0o700)
    (home / "data" / "tiled").mkdir(parents=True)
    shutil.copy(OBJECT_TYPES_FILE, home / "data" / "tiled" / "objecttypes.xml")
    assets = tmp_path_factory.mktemp("tilesets") / "assets"
    shutil.copytree(LEVELS_DIR.parent / "assets", assets)
    for name in ("tiles.tsx", "terrain.tsx"):
        tiled("--export-tileset", assets / name, assets / name, home=home)
    folders = {}
    for variant, options in VARIANTS.items():
        project = tmp_path_factory.mktemp(variant)
        shutil.copytree(LEVELS_DIR, project / "levels")
        shutil.copytree(assets, project / "assets")
        for level in SHIPPED:
            copy = project / "levels" / level.name
            tiled("--export-map", *options, copy, copy, home=home)
        folders[variant] = project / "levels"
    return folders


@functools.cache  # each original is loaded once, however many variants it is held to
def loaded(path: Path) -> Level:
    """``path`` as a play loads it, made :func:`folderless`."""
    return folderless(load_level(path))


@pytest.fixture
def fills_shared(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """The shipped levels' reach fills, for a check of copies equal to them."""
    return share_fills(monkeypatch)


@functools.cache  # the original is played once, however many variants it is held to
def final_state(level: Path) -> dict[str, object]:
    """Play ``level`` with its winning script; what the run ends with."""
    script = input_script(SCRIPTS / f"{level.stem}.txt")
    campaign = Campaign(level, loader=load_level)
    while campaign.outcome is Outcome.RUNNING and campaign.levels_completed == 0 and (
            campaign.ticks < MAX_TICKS):
        campaign.tick(script.held_at(campaign.ticks))
    player = campaign.world.player
    return {"ticks": campaign.ticks, "outcome": campaign.outcome,
            "levels_completed": campaign.levels_completed, "score": campaign.score,
            "coins": campaign.coins_collected, "stomps": campaign.enemies_stomped,
            "deaths": campaign.deaths, "player": (player.box, player.vx, player.vy,
                                                  player.on_ground)}


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_levels_resaved_by_tiled_pass_the_checker(variant: str, resaved: dict[str, Path],
                                                  fills_shared: list[Path]) -> None:
    maps = sorted(resaved[variant].glob("*.tmx"))
    result = call_main(levels_main, ["check", "--no-solve", "--jobs", "1", *maps])
    assert result.returncode == 0, result.stdout
    assert result.stdout.startswith(f"checked {len(maps)} map(s): all playable;"), result.stdout
    assert len(result.stdout.splitlines()) == 1, result.stdout
    assert fills_shared == []  # each re-saved level is its original, to its reach fill


@pytest.mark.parametrize("variant", sorted(VARIANTS))
@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_levels_resaved_by_tiled_load_the_same(level: Path, variant: str,
                                               resaved: dict[str, Path]) -> None:
    assert loaded(resaved[variant] / level.name) == loaded(level)


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_levels_resaved_by_tiled_play_the_same(variant: str, resaved: dict[str, Path]) -> None:
    """The first level, played to its exit (where the campaign loads the next level from the
    same folder): what a run ends with is what the original's ends with."""
    assert final_state(resaved[variant] / FIRST_LEVEL.name) == final_state(FIRST_LEVEL)
