"""Check one map the way ``python -m game.levels check`` does, and say what was found.

Where it sits: the command line (:mod:`game.checker.cli`) calls :func:`check_map` for
each map and prints the :class:`MapReport` as text lines or as JSON (for the Tiled
extension in ``levels/extensions/``, which lists the findings in Tiled's Issues panel).

What it teaches: one record per finding, with its place in named fields (the object id,
the tile, the layer), so the same check feeds a person reading a terminal and a program
selecting the object in an editor.

A map is first read (:func:`game.levels.loader.check_level`): errors there make it *bad*,
as do the designer checks' few errors (a next level that does not load ends the game when
this one is finished). Everything else is a warning with its place, and the map is then
judged (:mod:`game.checker.verdict`): solved, impossible or not decided; a recorded win
given with ``--proof`` makes it solved, whatever the warnings suggest.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from game.checker.designer_checks import designer_findings
from game.checker.solver import Effort
from game.checker.verdict import Kind, Verdict, judge, judge_proof
from game.levels.errors import (
    WARNINGS_SHOWN_PER_KIND,
    Findings,
    LevelError,
    LevelWarning,
    clipped,
    escaped,
    sentence,
    tile_place,
)
from game.levels.loader import check_level, load_level
from game.levels.reading import read_level_file
from game.sim.inputs import InputScript, InputScriptError
from game.sim.level import Level
from game.sim.tuning import Tuning

MAX_PROOF_BYTES = 4 * 1024 * 1024  # a recorded win: 300,000 events or more
FIX_PROOF = "record the win again with python -m game --level MAP --record SCRIPT"
FIX_PROOF_PATH = "give --proof the path of a script recorded with python -m game --record"


@dataclass(frozen=True)
class Finding:
    """One line of the check, with its place taken apart. Every text is escaped and cut
    as the printed line is (:func:`game.levels.errors.clipped`), so the JSON says what the
    text says, no more; the object, tile and layer come from the finding's
    :class:`~game.levels.errors.Place`, never from its text."""

    severity: str  # "error" or "warning"
    text: str  # the whole line, as printed
    where: str
    message: str
    fix: str
    object_id: int | None = None
    tile: tuple[int, int] | None = None
    layer: str | None = None

    @classmethod
    def of(cls, severity: str, path: Path | str, where: str, message: str,
           fix: str) -> Finding:
        """The finding ``PATH: where: message — fix``, its parts kept from ``where``."""
        layer = getattr(where, "layer", None)
        return cls(severity, sentence(path, where, message, fix, severity == "warning"),
                   clipped(where), clipped(message), clipped(fix),
                   getattr(where, "object_id", None), getattr(where, "tile", None),
                   clipped(layer) if layer is not None else None)

    def as_json(self) -> dict[str, object]:
        return {"severity": self.severity, "text": self.text, "place": self.where,
                "message": self.message, "fix": self.fix, "object_id": self.object_id,
                "tile": list(self.tile) if self.tile is not None else None,
                "layer": self.layer}


def _finding(item: LevelError | LevelWarning) -> Finding:
    severity = "warning" if isinstance(item, LevelWarning) else "error"
    return Finding.of(severity, item.path, item.where, item.problem, item.fix)


@dataclass
class MapReport:
    """What the check of one map found. Findings of one kind (one severity, one fix) are
    kept WARNINGS_SHOWN_PER_KIND at a time and the rest counted in one line, as the
    loader's warnings are, so a map that repeats one slip stays a short report."""

    path: Path
    findings: list[Finding] = field(default_factory=list)
    verdict: Kind | None = None  # None: not judged (bad, or --no-solve)
    tuning: Tuning | None = None  # the map's own physics, when they differ from the default
    proof_unread: bool = False  # the --proof script could not be read: the map is not to blame
    kinds: dict[tuple[str, str], int] = field(default_factory=dict)  # findings of a kind
    more: dict[tuple[str, str], int] = field(default_factory=dict)  # its "and N more" line

    @property
    def bad(self) -> bool:
        return any(f.severity == "error" for f in self.findings)

    def add(self, severity: str, where: str, message: str, fix: str) -> None:
        kind = (severity, fix)
        seen = self.kinds[kind] = self.kinds.get(kind, 0) + 1
        if seen <= WARNINGS_SHOWN_PER_KIND:
            self.findings.append(Finding.of(severity, self.path, where, message, fix))
            return
        self.count_more(severity, fix, seen - WARNINGS_SHOWN_PER_KIND)

    def count_more(self, severity: str, fix: str, count: int) -> None:
        """Say (or update) that ``count`` more findings like those above were left out."""
        kind = (severity, fix)
        line = Finding.of(severity, self.path, "", f"… and {count:,} more like the "
                          f"{severity}s above", fix)
        if kind in self.more:
            self.findings[self.more[kind]] = line
        else:
            self.more[kind] = len(self.findings)
            self.findings.append(line)

    def as_json(self) -> dict[str, object]:
        verdict = (self.verdict.value if self.verdict is not None
                   else "bad" if self.bad else "not searched")
        return {"path": escaped(str(self.path)), "verdict": verdict,
                "findings": [f.as_json() for f in self.findings]}


@dataclass(frozen=True)
class Options:
    """How hard to judge: no search at all, a work budget and seconds, or a recorded win."""

    solve: bool = True
    effort: Effort = field(default_factory=Effort)
    proof: Path | None = None
    command: str = "python -m game.levels"


def _add_verdict(report: MapReport, verdict: Verdict) -> None:
    report.verdict = verdict.kind
    if verdict.kind is Kind.SOLVED:
        return
    where = tile_place(*verdict.tile, verdict.layer) if verdict.tile is not None else ""
    # Impossible is an error; not decided is neither proven bad nor good: a warning line,
    # counted apart in the summary and given its own exit status.
    report.add("error" if verdict.kind is Kind.IMPOSSIBLE else "warning", where,
               verdict.finding, verdict.advice)


class ProofError(Exception):
    """A ``--proof`` script that cannot be read or is not an input script; the message is
    one sentence naming the script (and the line, when one is wrong)."""


def read_proof(path: Path) -> InputScript:
    """The recorded win given with ``--proof``, read as every file of a level is (a regular
    file, opened without waiting, at most MAX_PROOF_BYTES) and parsed."""
    try:
        data = read_level_file(path, Findings(path), "", "input script", MAX_PROOF_BYTES,
                               "record a shorter win", not_regular_fix=FIX_PROOF_PATH)
    except LevelError as error:
        raise ProofError(str(error)) from None
    try:
        return InputScript.parse(data.decode("utf-8"), escaped(str(path)))
    except UnicodeDecodeError:
        raise ProofError(escaped(f"{path}: the input script is not UTF-8 text — {FIX_PROOF}")
                         ) from None
    except InputScriptError as error:
        text = escaped(str(error))
        raise ProofError(text if " — " in text else f"{text} — {FIX_PROOF}") from None


def judge_level(path: Path, level: Level, options: Options) -> Verdict:
    """The verdict on a loaded map: from the recorded win when given, else searched."""
    if options.proof is not None:
        return judge_proof(level, options.proof, read_proof(options.proof))
    return judge(level, options.effort, options.command)


def check_map(path: Path, options: Options) -> MapReport:
    """Read ``path``, and when it loads and ``options.solve``, judge it."""
    report = MapReport(path)
    try:
        findings = check_level(path)
        report.findings += [_finding(w) for w in findings.warnings]
        for fix, count in findings.unshown.items():
            report.count_more("warning", fix, count)
        report.findings += [_finding(e) for e in findings.errors]
        if findings.errors:
            return report
        level = load_level(path)
        extra = designer_findings(path, level)
        report.findings = [f for f in report.findings  # the loader's warning, made an error
                           if not (f.severity == "warning" and "next_level" in f.where and any(
                               e[1] == f.where for e in extra))]
        for severity, where, message, fix in extra:
            report.add(severity, where, message, fix)
        if report.bad:
            return report
        tuning = Tuning().with_map_properties(level.properties)
        if tuning != Tuning():
            report.tuning = tuning
        if options.solve:
            _add_verdict(report, judge_level(path, level, options))
    except ProofError as error:  # the sentence names the script, not the map
        text = str(error)
        message, _, fix = text.partition(" — ")
        report.findings.append(Finding("error", text, "", clipped(message.rpartition(": ")[2]),
                                       clipped(fix)))
        report.proof_unread = True
    except Exception as error:  # a loader bug still gets a sentence
        report.add("error", "", f"the map could not be read ({type(error).__name__}: "
                   f"{error})", "open it in Tiled and save it again")
    return report
