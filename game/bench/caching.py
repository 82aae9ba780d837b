"""Chart 5, the caching myth: what reading a sprite's rect costs, and what copying it costs.

Where it sits: the fifth result of ``python -m game.bench``, a table rather than a plot.

What it teaches: people "cache" ``obj.rect`` with ``obj.rect.copy()`` or ``Rect(obj.rect)``
to make collision code faster, or "safer". Reading a body's ``obj.rect`` hands back the Rect
it last derived from its exact position (:attr:`game.sim.sprite.BoxSprite.rect`, worked out
again only when the box or the picture has changed); a copy builds a new Rect on top of
that, every time, and is stale the moment the sprite moves. Keep one exact position, derive
the Rect from it in one place, and read ``obj.rect`` wherever you need it.

Each form is timed in a loop over many bodies; the empty loop is timed too, so the table
gives the raw cost, the cost net of the loop, and what a copy costs on top of the plain read,
each a median of interleaved rounds with its 95 % interval. The last is a difference in ns,
not a ratio: what a copy adds is the question.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pygame

from game.bench import charts
from game.bench.intervals import median_interval, paired_difference
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
            for name, seconds in interleaved(cases, sizes.verdict_rounds, sizes.min_s).items()
            for r, s in enumerate(seconds)]


def table(rows: list[Row]) -> tuple[list[str], list[list[str]]]:
    """Header and body of the results table: each form's time, net of the loop, and what it
    costs on top of reading ``obj.rect``, all in ns with 95 % intervals.

    The cost over ``obj.rect`` is a difference, not a ratio: reading the attribute costs a
    few ns net of the loop, and a ratio to a few ns is mostly noise.
    """
    def times(method: str) -> list[float]:
        return values(rows, method=method, unit="ns/access")

    loop = times(LOOP)
    body = [[LOOP, median_interval(loop).text(), "", ""]]
    for form in FORMS:
        extra = ("" if form == FORMS[0] else
                 paired_difference(times(form), times(FORMS[0])).text())
        body.append([form, median_interval(times(form)).text(),
                     paired_difference(times(form), loop).text(), extra])
    return ["way of getting the rect", "ns per access", "net of the loop (ns)",
            "more than obj.rect (ns)"], body


def markdown(rows: list[Row]) -> str:
    return markdown_table(*table(rows))


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    header, body = table(rows)
    figure = charts.table_figure("The caching myth: reading obj.rect against copying it",
                                 header, body)
    return charts.save(figure, out / f"{CHART}.png", footnote)
