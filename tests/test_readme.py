"""The README stays true: its links and pictures resolve, its example commands run."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", ROOT / "levels" / "README.md", ROOT / "assets" / "README.md"]
LINK = re.compile(r"\]\(([^)\s]+)\)")
FENCE = re.compile(r"```sh\n(.*?)```", re.DOTALL)


def local_links(doc: Path) -> list[str]:
    return [link for link in LINK.findall(doc.read_text(encoding="utf-8"))
            if not re.match(r"[a-z]+:", link) and not link.startswith("#")]


@pytest.mark.parametrize("doc", DOCS, ids=[str(d.relative_to(ROOT)) for d in DOCS])
def test_every_link_and_picture_in_the_docs_resolves(doc: Path) -> None:
    links = local_links(doc)
    missing = [link for link in links if not (doc.parent / link.split("#")[0]).exists()]
    assert not missing, f"{doc.name} links to missing files: {missing}"


def example_commands() -> list[str]:
    """The README's ``sh`` blocks that run the game or its tools (not the installs)."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    commands = [block.replace("\\\n", " ").strip() for block in FENCE.findall(text)]
    return [c for c in commands if c.startswith(".venv/bin/python -m game")]


def test_the_readme_shows_example_commands() -> None:
    assert len(example_commands()) >= 2


@pytest.mark.parametrize("command", example_commands())
def test_the_readmes_example_commands_run(command: str, tmp_path: Path) -> None:
    args = shlex.split(command)
    args[0] = sys.executable
    args = [str(tmp_path / a) if a.endswith(".json") or a.endswith(".png") else a
            for a in args]
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    result = subprocess.run(args, cwd=ROOT, env=env, capture_output=True, text=True,
                            timeout=300, check=False)
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_test_the_readme_cites_exists() -> None:
    """A test the README names (in full, or cut short with ``...`` at either end) is a test
    function in ``tests/``, and a test file it names exists, so no citation outlives its test."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    files = {path.stem: path.read_text(encoding="utf-8")
             for path in (ROOT / "tests").glob("test_*.py")}
    defined = set(re.findall(r"^def (test_\w+)", "\n".join(files.values()), re.MULTILINE))
    cited = [token for token in re.findall(r"`([.\w]+)`", text)
             if token.startswith(("test_", "..._"))]
    assert len(cited) > 10

    def exists(token: str) -> bool:
        head_cut, tail_cut = token.startswith("..."), token.endswith("...")
        core = token.removeprefix("...").removesuffix("...")
        if head_cut and tail_cut:
            return any(core in name for name in defined)
        if head_cut:
            return any(name.endswith(core) for name in defined)
        if tail_cut:
            return any(name.startswith(core) for name in defined)
        return token in defined or token in files

    missing = [token for token in cited if not exists(token)]
    assert missing == [], f"the README cites tests that do not exist: {missing}"
