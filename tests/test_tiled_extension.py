"""The Tiled extension (levels/extensions/tile-hopper-check.js), run by Node.js against a
stand-in for Tiled's ``tiled`` and ``Process`` objects: each ``Process.exec`` the extension
makes really runs, with the program, arguments and working folder it asked for, so these
tests run exactly what Tiled would."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from game.levels import LEVELS_DIR
from tests.maps import write_tmx

NODE = shutil.which("node") or shutil.which("nodejs")
EXTENSION = LEVELS_DIR / "extensions" / "tile-hopper-check.js"
BASE_PYTHON = getattr(sys, "_base_executable", sys.executable)  # the venv's base: no game

pytestmark = pytest.mark.skipif(NODE is None, reason="Node.js is not installed")

# Tiled as far as the extension uses it. PROGRAMS maps the names the extension runs
# (python3, python) to real programs; a name not there fails to start, as in Tiled.
TILED = r"""
const fs = require("fs"), cp = require("child_process"), vm = require("vm");
const [script, mapFile, programsJson, appDir, stepsJson] = process.argv.slice(2);
const programs = JSON.parse(programsJson);
const steps = JSON.parse(stepsJson || "null") || [{ check: mapFile }];
const calls = [], issues = [], logs = [], callbacks = [], occurrences = [], selections = [];
let action = null;
function standInMap(file, ids) {  // one object layer with a 16x16 object of each id
    const map = { isTileMap: true, modified: false, fileName: file, tileWidth: 16,
                  tileHeight: 16, selectedObjects: [], area: null,
                  layers: [{ isObjectLayer: true, isGroupLayer: false,
                             objects: ids.map((id) => ({ id, x: 0, y: 0, width: 16,
                                                         height: 16 })) }] };
    map.selectedArea = { set: (rect) => { map.area = rect; } };
    return map;
}
function report(kind, text, callback) {  // Tiled's panel: one entry per severity and text,
    const found = issues.findIndex(([k, t]) => k === kind && t === text);  // the newest
    if (found >= 0) { callbacks[found] = callback; occurrences[found] += 1; return; }
    issues.push([kind, text]); callbacks.push(callback); occurrences.push(1);  // callback
}
globalThis.Qt = { rect: (x, y, w, h) => ({ x, y, w, h }) };
globalThis.tiled = {
    platform: "linux", applicationDirPath: appDir, mapEditor: null,
    activeAsset: standInMap(mapFile, []),
    registerAction: (id, callback) => { action = callback; return {}; },
    extendMenu: () => {}, trigger: () => {},
    alert: (text) => report("alert", text, null),
    log: (text) => logs.push(text),
    error: (text, activated) => report("error", text, activated),
    warn: (text, activated) => report("warn", text, activated),
};
globalThis.Process = class {
    constructor() { this.workingDirectory = ""; this.out = ""; this.err = ""; }
    exec(name, args) {
        calls.push({ name, args, cwd: this.workingDirectory });
        if (!(name in programs)) return -2;
        const run = cp.spawnSync(programs[name], args, { cwd: this.workingDirectory || undefined,
                                                         encoding: "utf8" });
        this.out = run.stdout; this.err = run.stderr;
        return run.status;
    }
    readStdOut() { return this.out; }
    readStdErr() { return this.err; }
    close() {}
};
vm.runInThisContext(fs.readFileSync(script, "utf8"), { filename: script });
for (const step of steps) {
    if ("check" in step) {  // open the map (objects of these ids) and press the action
        tiled.activeAsset = standInMap(step.check, step.objects || []);
        action();
    } else if ("save" in step) {  // the designer edits the map and saves it
        fs.writeFileSync(step.save, step.text, "utf8");
    } else {  // double-click the entry at this index (or the first with this text) in the panel
        const index = "activate" in step ? step.activate
            : issues.findIndex(([, text]) => text.includes(step.activate_text));
        if (index < 0) throw new Error(`no entry in the Issues panel says ${step.activate_text}`);
        const map = tiled.activeAsset;
        map.selectedObjects = []; map.area = null;
        const logged = logs.length;
        callbacks[index]();
        selections.push({ objects: map.selectedObjects.map((o) => o.id), area: map.area,
                          logs: logs.slice(logged) });
    }
}
process.stdout.write(JSON.stringify({ calls, issues, logs, occurrences, selections }));
"""


def run_extension(tmp_path: Path, map_file: Path, programs: dict[str, str],
                  steps: list[dict[str, Any]] | None = None) -> dict[str, Any]:
    """Press Map > Check Tile Hopper Map with ``map_file`` open (or take ``steps``: open a map
    and check it, ``{"check": PATH, "objects": [IDS]}``, save a map with new text,
    ``{"save": PATH, "text": TEXT}``, or double-click the Issues panel's entry at an index,
    ``{"activate": N}``, or the first entry whose text holds TEXT, ``{"activate_text":
    TEXT}``); what the extension ran, what it put in the
    Issues panel (and how many times each entry was reported) and the Console, and what
    each double-click selected."""
    harness = tmp_path / "tiled-stand-in.js"
    harness.write_text(TILED, encoding="utf-8")
    tiled_folder = tmp_path / "tiled-app"
    tiled_folder.mkdir(exist_ok=True)
    assert NODE is not None
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    result = subprocess.run([NODE, str(harness), str(EXTENSION), str(map_file),
                             json.dumps(programs), str(tiled_folder),
                             json.dumps(steps)], capture_output=True,
                            text=True, timeout=120, check=False, env=env)
    assert result.returncode == 0, result.stderr
    answer: dict[str, Any] = json.loads(result.stdout)
    return answer


def hostile_pack(tmp_path: Path, folder: str = "levels") -> tuple[Path, Path]:
    """A downloaded pack: a map with no Player in ``pack/FOLDER``, beside which (and in the
    pack's top) lie a ``game/`` package that says "solved" and an ``argparse.py``, each
    leaving a marker file when imported."""
    pack = tmp_path / "pack"
    levels = pack / folder
    levels.mkdir(parents=True)
    map_file = write_tmx(levels, ["          D", "###########"], name="no-player.tmx")
    marker = tmp_path / "ran"
    plant = f"open({str(marker)!r}, 'a').write(__name__ + '\\n')\n"
    fake = ('print(\'{"maps": [{"path": "x", "verdict": "solved", "findings": []}], '
            '"summary": "checked 1 map(s): all playable, 1 solved", "status": 0}\')\n')
    for top in (pack, levels):
        (top / "game" / "levels").mkdir(parents=True)
        (top / "game" / "__init__.py").write_text(plant, encoding="utf-8")
        (top / "game" / "__main__.py").write_text(plant + fake, encoding="utf-8")
        (top / "game" / "levels" / "__init__.py").write_text(plant, encoding="utf-8")
        (top / "game" / "levels" / "__main__.py").write_text(plant + fake, encoding="utf-8")
        (top / "argparse.py").write_text(plant, encoding="utf-8")
    return pack, map_file


def files_in(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and "__pycache__" not in p.parts}


@pytest.mark.parametrize("folder", ["levels", "downloads"])
def test_a_map_from_a_pack_runs_none_of_the_packs_code(tmp_path: Path, folder: str) -> None:
    pack, map_file = hostile_pack(tmp_path, folder)
    before, project_before = files_in(pack), files_in(LEVELS_DIR)
    answer = run_extension(tmp_path, map_file, {"python3": sys.executable})
    assert not (tmp_path / "ran").exists(), (tmp_path / "ran").read_text(encoding="utf-8")
    errors = [text for kind, text in answer["issues"] if kind == "error"]
    assert any("this map has no Player" in text for text in errors), answer["issues"]
    call = answer["calls"][0]
    assert call["args"][0] == "-I" and call["args"][-2:] == ["--", str(map_file)]
    assert Path(call["cwd"]) == tmp_path / "tiled-app"  # never the map's folder
    assert files_in(pack) == before and files_in(LEVELS_DIR) == project_before


def test_the_check_uses_the_python_that_has_the_game(tmp_path: Path) -> None:
    probe = subprocess.run([BASE_PYTHON, "-I", "-c", "import game"], capture_output=True,
                           cwd=tmp_path, check=False)
    if probe.returncode == 0:
        pytest.skip("the base Python has the game installed too")
    _, map_file = hostile_pack(tmp_path)
    answer = run_extension(tmp_path, map_file,
                           {"python3": BASE_PYTHON, "python": sys.executable})
    assert [c["name"] for c in answer["calls"]] == ["python3", "python"]
    assert any("this map has no Player" in text for _, text in answer["issues"])
    answer = run_extension(tmp_path, map_file, {"python3": BASE_PYTHON})
    assert [kind for kind, _ in answer["issues"]] == ["error"]
    assert "the game is not installed for python3" in answer["issues"][0][1]
    assert not (tmp_path / "ran").exists()


def test_the_search_in_tiled_is_bounded_by_a_budget_of_moves(tmp_path: Path) -> None:
    """Tiled waits while the check runs, so its search tries at most 1,000 moves; the
    moving-parts level needs about 3,000, and is left not decided with the bound named."""
    answer = run_extension(tmp_path, LEVELS_DIR / "04-moving-parts.tmx",
                           {"python3": sys.executable})
    assert answer["calls"][0]["args"][6:8] == ["--budget", "1000"]
    warnings = [text for kind, text in answer["issues"] if kind == "warn"]
    assert len(warnings) == 1 and "not decided" in warnings[0], answer["issues"]
    assert "its budget of 1,000 moves (1,0" in warnings[0]


def test_the_issues_panel_gets_every_text_escaped(tmp_path: Path) -> None:
    """Whatever the checker prints, no newline, control or bidi override reaches Tiled."""
    forged = {"maps": [{"path": "a.tmx", "verdict": "bad", "findings": [
        {"severity": "error", "text": "a.tmx: layer 'x\nchecked 1 map(s): all playable':"
                                      " \u202etxt.exe\x1b[2J", "object_id": None,
         "tile": None, "layer": None}]}],
        "summary": "checked 1 map(s)\r\u2066", "status": 1}
    fake = tmp_path / "fake-python"
    fake.write_text(f"#!{sys.executable}\nimport sys\n"
                    f"sys.stdout.write({json.dumps(forged, ensure_ascii=False)!r})\n",
                    encoding="utf-8")
    fake.chmod(0o755)
    answer = run_extension(tmp_path, LEVELS_DIR / "01-first-steps.tmx", {"python3": str(fake)})
    shown = [text for _, text in answer["issues"]] + answer["logs"]
    assert ("a.tmx: layer 'x\\nchecked 1 map(s): all playable': \\u202etxt.exe\\x1b[2J"
            in shown)
    assert "checked 1 map(s)\\r\\u2066" in shown
    assert all(text.isprintable() for text in shown), shown


CAVE = ["                ", "                ", " P           D  ", "################"]
BURIED_FLAG = '<object id="9" name="flag" type="Checkpoint" x="96" y="40" width="16" height="16"/>'


def test_a_checkpoint_finding_selects_the_flag_not_a_tile(tmp_path: Path) -> None:
    map_file = write_tmx(tmp_path, CAVE, extra_objects=BURIED_FLAG)
    answer = run_extension(tmp_path, map_file, {"python3": sys.executable},
                           [{"check": str(map_file), "objects": [1, 2, 9]},
                            {"activate_text": "Checkpoint"}])
    assert len([text for _, text in answer["issues"] if "Checkpoint" in text]) == 1
    assert answer["selections"] == [{"objects": [9], "area": None, "logs": []}]


def test_each_check_is_told_apart_and_a_finding_it_did_not_make_again_selects_nothing(
        tmp_path: Path) -> None:
    """Tiled 1.8's scripts cannot clear the Issues panel: each check logs a separator, and
    the entries of an earlier check of the map that the latest did not find again say so
    when activated instead of selecting; an entry found again selects as it did."""
    map_file = write_tmx(tmp_path, CAVE, extra_objects=BURIED_FLAG + '<object id="8" '
                         'type="Checkpoint" x="160" y="40" width="16" height="16"/>')
    check = {"check": str(map_file), "objects": [1, 2, 8, 9]}
    fixed = map_file.read_text(encoding="utf-8").replace(
        'id="8" type="Checkpoint" x="160" y="40"', 'id="8" type="Checkpoint" x="160" y="16"')
    other = write_tmx(tmp_path, CAVE, name="other.tmx")
    flag_9, flag_8 = "object #9 'flag'", "object #8 ''"
    answer = run_extension(tmp_path, map_file, {"python3": sys.executable}, [
        check, {"check": str(other), "objects": [1, 2]},
        {"save": str(map_file), "text": fixed}, check,  # flag #8 now stands on the ground
        {"activate_text": flag_9}, {"activate_text": flag_8}])  # as the first check found them
    texts = [text for _, text in answer["issues"]]  # entries are only ever added, in order
    first = next(n for n, text in enumerate(texts) if flag_9 in text)
    separators = [line for line in answer["logs"] if line.startswith("==== Tile Hopper check")]
    assert separators == [f"==== Tile Hopper check {n}: {path} ==== (the Issues panel keeps "
                          "the findings of earlier checks until you press its Clear button)"
                          for n, path in ((1, map_file), (2, other), (3, map_file))]
    assert answer["occurrences"][first] == 2  # found again by the third check
    flag, stale = answer["selections"]
    assert flag == {"objects": [9], "area": None, "logs": []}
    assert stale["objects"] == [] and stale["area"] is None
    assert stale["logs"] == [f"Tile Hopper: this finding is from an earlier check of {map_file} "
                             "and the latest check did not find it again; press Clear in the "
                             "Issues panel to remove the findings of earlier checks"]
