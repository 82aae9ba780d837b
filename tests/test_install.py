"""The game installs like any Python program and plays from any folder.

The wheel is built from a copy of the repository by setuptools' own build hook (the one
pip calls), with this environment's setuptools, which the ``dev`` extra keeps at the version
the build asks for (``[build-system]``): pip's isolated build would first install a second
setuptools for the one build. It is installed into a fresh virtual environment (by this
environment's pip, so the new one needs no pip of its own), and run as ``tile-hopper`` from a
folder that holds nothing of the game: the campaign, the tileset, the art and the sounds must
all come from inside the installed package. Building and installing take seconds (about 6 s
of CPU), so the test carries the ``install`` mark (``pytest -m "not install"`` skips it); CI
runs it.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest
from packaging.requirements import Requirement

tomllib = pytest.importorskip("tomllib")  # Python 3.11 and later read TOML themselves

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ("pyproject.toml", "README.md", "game", "levels", "assets")
INSTALL_TIMEOUT_S = 900  # a busy machine, wheels from the local cache or PyPI


def declared_packages() -> set[str]:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    return set(config["tool"]["setuptools"]["packages"])


def test_the_build_lists_every_package_of_the_game() -> None:
    found = {".".join(init.parent.relative_to(ROOT).parts)
             for init in (ROOT / "game").rglob("__init__.py")}
    assert found - declared_packages() == set()


def test_the_build_carries_the_campaign_and_the_assets_inside_the_package() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    mapped = config["tool"]["setuptools"]["package-dir"]
    assert mapped["game.data.levels"] == "levels" and mapped["game.data.assets"] == "assets"
    assert {"tile-hopper", "tile-hopper-levels"} <= set(config["project"]["scripts"])


def test_this_environment_has_the_setuptools_the_build_asks_for() -> None:
    """The wheel below is built with this environment's setuptools, not an isolated one."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    [wanted] = [Requirement(r) for r in config["build-system"]["requires"]]
    assert wanted.name == "setuptools" and wanted.specifier.contains(version("setuptools")), (
        f"pip install '{wanted}' (the test extra names it)")
    tools = [Requirement(r) for r in config["project"]["optional-dependencies"]["test"]]
    assert wanted in tools


def run(command: list[str | Path], cwd: Path, env: dict[str, str] | None = None
        ) -> subprocess.CompletedProcess[str]:
    result = subprocess.run([str(part) for part in command], cwd=cwd, env=env,
                            capture_output=True, text=True, timeout=INSTALL_TIMEOUT_S,
                            check=False)
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    return result


@pytest.mark.install
def test_a_wheel_installed_in_a_fresh_environment_plays_level_one_from_any_folder(
        tmp_path: Path) -> None:
    source = tmp_path / "source"
    for name in SOURCES:
        if (ROOT / name).is_dir():
            shutil.copytree(ROOT / name, source / name,
                            ignore=shutil.ignore_patterns("__pycache__", "charts",
                                                          "screenshots"))
        else:
            source.mkdir(exist_ok=True)
            shutil.copy2(ROOT / name, source / name)
    wheels = tmp_path / "wheels"
    run([sys.executable, "-c", "import sys, setuptools.build_meta as build; "
         "build.build_wheel(sys.argv[1])", wheels], source)
    [wheel] = wheels.glob("tile_hopper-*.whl")

    venv = tmp_path / "venv"  # fresh and empty: this environment's pip installs into it
    run([sys.executable, "-m", "venv", "--without-pip", venv], tmp_path)
    bin_dir = venv / ("Scripts" if os.name == "nt" else "bin")
    run([sys.executable, "-m", "pip", "--python", bin_dir / "python", "install", "-q",
         "--no-compile", wheel], tmp_path)  # byte-compiling the files proves nothing here

    elsewhere = tmp_path / "elsewhere"  # nothing of the game here, nor above it
    elsewhere.mkdir()
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    env.pop("PYTHONPATH", None)
    run([bin_dir / "tile-hopper", "--headless", "--ticks", "600", "--report", "r.json",
         "--screenshot", "shot.png"], elsewhere, env)
    report = json.loads((elsewhere / "r.json").read_text(encoding="utf-8"))
    assert report["ticks"] == 600
    assert report["level"].endswith("game/data/levels/01-first-steps.tmx")
    assert "site-packages" in report["level"] or "Lib" in report["level"]
    assert (elsewhere / "shot.png").stat().st_size > 0  # the art came from the package

    run([bin_dir / "tile-hopper", "--headless", "--level", "over-the-gaps", "--ticks", "1",
         "--report", "named.json"], elsewhere, env)  # a shipped level, by its name
    named = json.loads((elsewhere / "named.json").read_text(encoding="utf-8"))["level"]
    assert named.endswith("game/data/levels/02-over-the-gaps.tmx")

    # Every shipped map is in the package as it is here (tests/test_levels.py checks them
    # all, tests/test_solver.py solves them), so the installed checker needs to read only one.
    installed = Path(report["level"]).parent
    for level in sorted((ROOT / "levels").rglob("*.tmx")):
        shipped = installed / level.relative_to(ROOT / "levels")
        assert shipped.read_bytes() == level.read_bytes(), shipped
    checked = run([bin_dir / "tile-hopper-levels", "check", "--no-solve", report["level"]],
                  elsewhere, env)
    assert "all playable" in checked.stdout


def test_the_build_carries_the_showcase_maps_and_the_tiled_extension() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    mapped = config["tool"]["setuptools"]["package-dir"]
    data = config["tool"]["setuptools"]["package-data"]
    assert mapped["game.data.levels.showcase"] == "levels/showcase"
    assert mapped["game.data.levels.extensions"] == "levels/extensions"
    assert "*.tmx" in data["game.data.levels.showcase"]
    assert "*.js" in data["game.data.levels.extensions"]
