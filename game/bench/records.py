"""Measurements as rows: one long-format CSV per chart, so every figure can be checked.

Where it sits: every bench module returns :class:`Row` objects; :mod:`game.bench.run`
writes them with :func:`write_csv`, and the charts are drawn from the same rows.

What it teaches: keep the raw measurements, not just the picture. In *long* format each row is
one number with everything needed to read it: which chart, which method, at which parameter
(a size, a speed, a shape family), in which round, and its unit. A spreadsheet or a few lines
of Python can then redo any median or ratio printed in the charts' README.

>>> rows = [Row("caching", "obj.rect", "access", 0, 41.5, "ns/access")]
>>> csv_text(rows).splitlines()
['chart,method,parameter,round,value,unit', 'caching,obj.rect,access,0,41.5,ns/access']
>>> values(rows, method="obj.rect", unit="ns/access")
[41.5]
>>> print(markdown_table(["method", "ns"], [["obj.rect", "41.5"]]))
| method | ns |
|---|---|
| obj.rect | 41.5 |
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import NamedTuple

from game.app.files import read_small_text, write_text_atomically

COLUMNS = ("chart", "method", "parameter", "round", "value", "unit")
MAX_CSV_BYTES = 64 * 1024 * 1024  # a full run's measurements are well under 1 MB


class Row(NamedTuple):
    """One measured number. ``round`` is 0 for figures that are computed, not timed."""

    chart: str
    method: str
    parameter: str
    round: int
    value: float
    unit: str


def csv_text(rows: Iterable[Row]) -> str:
    """The rows as CSV text with a header line."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(COLUMNS)
    for row in rows:
        writer.writerow([row.chart, row.method, row.parameter, row.round,
                         f"{row.value:.6g}", row.unit])
    return buffer.getvalue()


def write_csv(path: Path, rows: Iterable[Row]) -> None:
    """Write the rows atomically (:func:`game.app.files.write_text_atomically`)."""
    write_text_atomically(path, csv_text(rows))


def read_csv(path: Path, *, just_written: bool = False) -> list[Row]:
    """Rows back from a file written by :func:`write_csv`, read through the one bounded
    open (:func:`game.app.files.read_small_text`); ``just_written``: the run's own output,
    read back, which is not an input the run may not write again."""
    text = read_small_text(path, MAX_CSV_BYTES, "the measurements", updated=just_written)
    return [Row(r["chart"], r["method"], r["parameter"], int(r["round"]),
                float(r["value"]), r["unit"])
            for r in csv.DictReader(io.StringIO(text, newline=""))]


def values(rows: Iterable[Row], *, method: str | None = None, parameter: str | None = None,
           unit: str | None = None) -> list[float]:
    """The values of the rows matching every filter given."""
    return [row.value for row in rows
            if (method is None or row.method == method)
            and (parameter is None or row.parameter == parameter)
            and (unit is None or row.unit == unit)]


def markdown_table(header: Sequence[str], body: Iterable[Sequence[str]]) -> str:
    """A GitHub-flavoured markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in body]
    return "\n".join(lines)
