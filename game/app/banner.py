"""The level-end banner: a short pause after an exit with the level's tally, and a sound.

Where it sits: in the window only (:mod:`game.app.window`). When a tick reports the exit, the
window stops ticking, keeps the finished level on screen and shows a :class:`Banner` over it:
the time, the coins taken of those on offer, the enemies stomped, the points scored,
whether the time beat the best, and, for a level with a target time, whether it earned the
medal (:mod:`game.app.goals`). A level played with an assist on says so, and keeps no best.
Its lines appear one after another, the tally sound plays when the last is up, and play
goes on after :data:`BANNER_S` seconds (or at once on Enter or A, once the tally is up).

The banner costs no simulation ticks: it is a pause of the window, like the pause menu, so
a headless run, a scripted run and their reports are the same with or without it.

What it teaches:
  * **A moment is a little timeline.** Everything the banner does is a function of the
    seconds since it appeared: how many lines show, when the sound plays, when it ends. The
    window only feeds it the frame time, so there is no hidden timer to get out of step.
"""

from __future__ import annotations

from dataclasses import dataclass

import pygame

from game.app.assets import Assets
from game.app.goals import earns_medal, of_total, target_ticks
from game.app.hud import DIM_TEXT, GOLD, TEXT_COLOR, draw_text
from game.app.screens import (
    COLUMN_GAP_PX,
    LINE_GAP_PX,
    PANEL_PAD_PX,
    dim,
    draw_heading,
    draw_panel,
    format_seconds,
    heading_h,
)
from game.sim.campaign import LevelResult
from game.sim.tuning import TICK_S
from game.sim.world import World

BANNER_S = 3.0  # how long the banner stays up unless skipped
LINE_EVERY_S = 0.25  # one more line of the tally appears this often
SKIP_AFTER_S = 0.5  # Enter or A ends the banner once it has been up this long
HEADING = "Level clear!"
NEW_BEST_BLINK_HZ = 3.0
NEW_BEST = "new best!"
MEDAL_WON = "medal!"
ASSISTED = "assisted: not kept"  # the Best row of a level played with an assist on
TALLY_SOUND = "tally"


def format_ticks(ticks: int) -> str:
    """A time in ticks as the banner shows it.

    >>> format_ticks(861), format_ticks(60)
    ('14.35 s', '1.00 s')
    """
    return format_seconds(ticks * TICK_S)


def tally_lines(result: LevelResult, best_before_ticks: int | None,
                target: int | None = None) -> list[tuple[str, str]]:
    """The banner's rows, label and value, in the order they appear; a Target row when the
    level has a ``target`` time (in ticks).

    >>> from pathlib import Path
    >>> r = LevelResult(Path("a.tmx"), "A", 900, 9, 12, 1, 2, 14)
    >>> tally_lines(r, 1000)[-1], tally_lines(r, 800)[-1], tally_lines(r, None)[-1]
    (('Best', 'new best!'), ('Best', '13.33 s'), ('Best', 'first clear'))
    >>> tally_lines(r, None, 900)[-1], tally_lines(r, None, 899)[-1]
    (('Target', '15.00 s medal!'), ('Target', '14.98 s'))
    """
    if result.assisted:
        best = ASSISTED
    elif best_before_ticks is None:
        best = "first clear"
    elif result.ticks < best_before_ticks:
        best = NEW_BEST
    else:
        best = format_ticks(best_before_ticks)
    lines = [("Time", format_ticks(result.ticks)),
             ("Coins", of_total(result.coins, result.coins_total)),
             ("Stomps", of_total(result.stomps, result.enemies_total)),
             ("Score", f"+{result.score}"),
             ("Best", best)]
    if target is not None:
        medal = earns_medal(result.ticks, target, result.assisted)
        lines.append(("Target", f"{format_ticks(target)} {MEDAL_WON}" if medal
                      else format_ticks(target)))
    return lines


@dataclass
class Banner:
    """The banner for one finished level, and how long it has been up."""

    result: LevelResult
    best_before_ticks: int | None  # the level's best time before this finish, if any
    world: World | None = None  # the level just finished, shown still behind the banner
    shown_s: float = 0.0
    sounded: bool = False

    @property
    def lines(self) -> list[tuple[str, str]]:
        target = None if self.world is None else target_ticks(self.world.level.properties)
        return tally_lines(self.result, self.best_before_ticks, target)

    def lines_shown(self) -> int:
        """How many tally lines are up now: one more every :data:`LINE_EVERY_S`."""
        return min(len(self.lines), int(self.shown_s / LINE_EVERY_S))

    def advance(self, frame_s: float) -> str | None:
        """Let ``frame_s`` seconds pass; return the name of a sound to play now, if any."""
        self.shown_s += frame_s
        if not self.sounded and self.lines_shown() == len(self.lines):
            self.sounded = True
            return TALLY_SOUND
        return None

    def done(self) -> bool:
        return self.shown_s >= BANNER_S

    def skippable(self) -> bool:
        return self.shown_s >= SKIP_AFTER_S

    def draw(self, target: pygame.Surface, assets: Assets) -> None:
        """Dim the finished level and draw the heading, the level's title and the tally."""
        dim(target)
        font, big = assets.font, assets.big_font
        lines = self.lines
        label_w = max(font.size(label)[0] for label, _ in lines)
        value_w = max(font.size(value)[0] for _, value in lines)
        title = self.result.title
        inner_w = max(label_w + COLUMN_GAP_PX + value_w, big.size(HEADING)[0],
                      font.size(title)[0])
        line_h = font.get_linesize() + LINE_GAP_PX
        box = pygame.Rect(0, 0, inner_w + 4 * PANEL_PAD_PX,
                          heading_h(assets) + (len(lines) + 1) * line_h + 3 * PANEL_PAD_PX)
        box.center = target.get_rect().center
        draw_panel(target, box)
        y = draw_heading(target, assets, HEADING, (box.centerx, box.top + PANEL_PAD_PX)).bottom
        draw_text(target, font, title, (box.centerx, y), DIM_TEXT, anchor="midtop")
        y += line_h + PANEL_PAD_PX
        blink_on = int(self.shown_s * NEW_BEST_BLINK_HZ * 2) % 2 == 0
        for label, value in lines[:self.lines_shown()]:
            draw_text(target, font, label, (box.left + 2 * PANEL_PAD_PX, y), DIM_TEXT)
            best = value == NEW_BEST or value.endswith(MEDAL_WON)
            if not best or blink_on:
                draw_text(target, font, value, (box.right - 2 * PANEL_PAD_PX, y),
                          GOLD if best else TEXT_COLOR, anchor="topright")
            y += line_h
