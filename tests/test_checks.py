"""One bar for everything: the README's test command is what CI runs, it type-checks the tests
as strictly as the game, and as the oldest Python the package says it supports."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import hypothesis  # noqa: F401  # loaded here whichever test file runs first
import pytest
from _pytest.assertion.rewrite import AssertionRewritingHook

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")
PYPROJECT = (ROOT / "pyproject.toml").read_text(encoding="utf-8")  # tomllib is 3.11+


def setting(name: str) -> str:
    """The quoted value of ``name = "..."`` in pyproject.toml (each name appears once)."""
    (value,) = re.findall(rf'^{re.escape(name)}\s*=\s*"([^"]*)"', PYPROJECT, re.MULTILINE)
    return str(value)


def readme_test_command() -> str:
    blocks = re.findall(r"```sh\n(.*?)\n```", README, re.DOTALL)
    return next(str(block) for block in blocks if ".venv/bin/pytest" in block)


def test_ci_runs_exactly_the_readmes_test_command() -> None:
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert readme_test_command() in ci


def test_the_test_command_type_checks_the_tests_as_strictly_as_the_game() -> None:
    assert ".venv/bin/mypy --strict game tests " in readme_test_command()


def test_mypy_checks_the_oldest_python_the_package_supports() -> None:
    requires = setting("requires-python")
    oldest = re.fullmatch(r">=\s*(\d+\.\d+)", requires)
    assert oldest is not None, f"requires-python {requires!r} does not name an oldest version"
    assert setting("python_version") == oldest.group(1)


def test_the_test_run_loads_hypothesis_without_rewriting_its_asserts(
        pytestconfig: pytest.Config) -> None:
    """The plugin is named in pyproject.toml, not discovered: a discovered plugin's whole
    package has its asserts rewritten at every start, where no bytecode is cached."""
    assert pytestconfig.pluginmanager.has_plugin("_hypothesis_pytestplugin")
    loader = sys.modules["hypothesis"].__spec__.loader  # type: ignore[union-attr]
    assert not isinstance(loader, AssertionRewritingHook)
