"""Chart 5, the caching myth: what reading a sprite's rect costs, and what copying it costs.

Where it sits: the fifth result of ``python -m game.bench``, a table rather than a plot.

What it teaches: people "cache" ``obj.rect`` with ``obj.rect.copy()`` or ``Rect(obj.rect)``
to make collision code faster, or "safer". Reading ``obj.rect`` is one attribute lookup
that hands back the same Rect object; a copy builds a new Rect every time, which costs more
than the lookup it was meant to save, and a copy is stale the moment the sprite moves. Keep
one exact position and derive the Rect from it in one place (:meth:`game.sim.body.Body.place`),
then read ``obj.rect`` wherever you need it.

Each form is timed in a loop over many bodies; the empty loop is timed too, so the table
gives both the raw cost and the cost net of the loop.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from statistics import median

import pygame

from game.bench import charts
from game.bench.records import Row, markdown_table, values
from game.bench.sizes import Sizes
from game.bench.timing import Case, interleaved
from game.collision.aabb import Box
from game.sim.body import Body

CHART = "caching"
LOOP = "the loop alone (for obj in bodies)"
FORMS = ("obj.rect", "obj.rect.copy()", "Rect(obj.rect)")


def loops(bodies: list[Body]) -> dict[str, Callable[[], None]]:
    """The empty loop and one loop per way of getting at a body's rect."""
    rect_type = pygame.Rect

    def loop_only() -> None:
        for obj in bodies:
            obj  # noqa: B018  (the loop's own cost, to subtract)

    def read() -> None:
        for obj in bodies:
            obj.rect  # noqa: B018

    def copy() -> None:
        for obj in bodies:
            obj.rect.copy()

    def construct() -> None:
        for obj in bodies:
            rect_type(obj.rect)

    return {LOOP: loop_only, FORMS[0]: read, FORMS[1]: copy, FORMS[2]: construct}


def measure(sizes: Sizes) -> list[Row]:
    bodies = [Body(Box(i * 3.5, 40.0, 12, 14)) for i in range(sizes.cache_objects)]
    cases = [Case(name, run, ops=len(bodies)) for name, run in loops(bodies).items()]
    return [Row(CHART, name, "access", r, s * 1e9, "ns/access")
            for name, seconds in interleaved(cases, sizes.rounds, sizes.min_s).items()
            for r, s in enumerate(seconds)]


def table(rows: list[Row]) -> tuple[list[str], list[list[str]]]:
    """Header and body of the results table: raw, net of the loop, and relative cost."""
    loop = median(values(rows, method=LOOP, unit="ns/access"))
    net = {form: median(values(rows, method=form, unit="ns/access")) - loop for form in FORMS}
    body = [[LOOP, f"{loop:.0f}", "", ""]]
    for form in FORMS:
        raw = net[form] + loop
        relative = net[form] / net[FORMS[0]] if net[FORMS[0]] > 0 else float("nan")
        body.append([form, f"{raw:.0f}", f"{net[form]:.0f}", f"{relative:.1f}x"])
    return ["way of getting the rect", "ns per access", "net of the loop (ns)",
            "net cost vs obj.rect"], body


def markdown(rows: list[Row]) -> str:
    return markdown_table(*table(rows))


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    header, body = table(rows)
    figure = charts.table_figure("The caching myth: reading obj.rect against copying it",
                                 header, body)
    return charts.save(figure, out / f"{CHART}.png", footnote)
