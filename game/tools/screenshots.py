"""``python -m game.tools.screenshots``: remake the README's pictures from the game itself.

Where it sits: beside the game, not in it. Each picture is one scripted headless run of a
shipped level, stopped at a chosen tick and saved with ``--screenshot`` (and ``--debug``
where the picture shows the overlay), exactly as a reader could run it by hand: the command
for each is printed as it goes. The pictures land in ``assets/screenshots/``.

Two pictures cannot come from a headless run, which has neither the level-end banner (a
pause of the window) nor the F5 key: ``level-end.png`` and ``debug-full-panel.png`` play the
first level's winning script in this process and draw the frame with the window's own drawing
code, :func:`game.app.frame.render_frame` (with the overlay's full panel, as after one press
of F5) and :meth:`game.app.banner.Banner.draw`. ``menus.png`` draws the options screen and the
level select side by side with the window's own drawing code, for a player who has finished
the first two levels (each played through its winning script). ``endings.png`` is drawn the
same way: a
checkpoint's lantern just lit (with the window's effects), game over over the last frame of
a run that lost every life, and the credits.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pygame

from game.app.assets import load_assets
from game.app.banner import BANNER_S, Banner
from game.app.debug_overlay import PanelMode
from game.app.effects import Effects
from game.app.files import save_image
from game.app.frame import render_frame
from game.app.hud import draw_text
from game.app.menus import GAME_OVER_ITEMS, RETRY, campaign_levels, level_entries
from game.app.options import GAME_SPEED, OPTION_ITEMS
from game.app.options_screen import draw_options
from game.app.places import place_of
from game.app.render import WorldRenderer
from game.app.run import input_script
from game.app.saves import Progress
from game.app.screens import draw_credits, draw_game_over, draw_level_select
from game.app.settings import Settings
from game.levels import FIRST_LEVEL, LEVELS_DIR, load_level
from game.levels.closed_output import quiet_when_output_closes
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action
from game.sim.sprite import ANIMATION_HZ
from game.sim.tuning import TICK_S
from game.sim.world import EventKind, Measure

ROOT = Path(__file__).resolve().parents[2]
SHOTS = ROOT / "assets" / "screenshots"


@dataclass(frozen=True)
class Shot:
    """One picture: which level, how far into its winning script (or with no input at all,
    for a showcase map that has none), overlay or not."""

    name: str
    level: str
    ticks: int
    debug: bool
    scripted: bool = True

    def command(self) -> list[str]:
        stem = Path(self.level).stem
        inputs = ["--inputs", f"tests/scripts/{stem}.txt"] if self.scripted else []
        args = [sys.executable, "-m", "game", "--headless", "--level", self.level, *inputs,
                "--ticks", str(self.ticks), "--screenshot", f"assets/screenshots/{self.name}.png"]
        return [*args, "--debug"] if self.debug else args


SHOTS_TO_TAKE = (
    Shot("first-steps", "levels/01-first-steps.tmx", 400, debug=False),
    Shot("debug-overlay", "levels/01-first-steps.tmx", 212, debug=True),
    Shot("debug-stomp", "levels/01-first-steps.tmx", 335, debug=True),
    Shot("moving-parts", "levels/04-moving-parts.tmx", 579, debug=True),
    Shot("debug-fast-fall", "levels/showcase/fast-fall.tmx", 1, debug=True, scripted=False),
)


def level_end_picture(path: Path) -> None:
    """The first level's banner, fully up, over the level just finished, as the window
    draws it (a first clear: no best time saved before)."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    script = input_script(ROOT / "tests" / "scripts" / f"{FIRST_LEVEL.stem}.txt")
    campaign = Campaign(FIRST_LEVEL, loader=lambda level: load_level(level, images=True))
    finishing = campaign.world
    while not campaign.results:
        finishing = campaign.world
        campaign.tick(script.held_at(campaign.ticks))
    banner = Banner(campaign.results[-1], None, world=finishing)
    banner.advance(BANNER_S / 2)  # every line is up by then
    frame = render_frame(campaign, debug=False, world=finishing)
    banner.draw(frame, load_assets())
    save_image(frame, path)
    pygame.display.quit()


FULL_PANEL_TICKS = 335  # just after the first stomp: the contact lines have something to say
MS_PER_S = 1000.0


def full_panel_picture(path: Path) -> None:
    """The first level's winning script played to :data:`FULL_PANEL_TICKS`, drawn with the
    overlay's full panel, as the window shows it after F5; the tick time is the last tick's,
    measured here."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    script = input_script(ROOT / "tests" / "scripts" / f"{FIRST_LEVEL.stem}.txt")
    campaign = Campaign(FIRST_LEVEL, loader=lambda level: load_level(level, images=True),
                        measure=Measure(queries=True))
    tick_s = 0.0
    while campaign.ticks < FULL_PANEL_TICKS:
        started = time.perf_counter()
        campaign.tick(script.held_at(campaign.ticks))
        tick_s = time.perf_counter() - started
    frame = render_frame(campaign, debug=True, update_ms=tick_s * MS_PER_S,
                         panel=PanelMode.FULL)
    save_image(frame, path)
    pygame.display.quit()


PLACES_TICK = 300  # each level's frame on the contact sheet: 5 s into its winning script
SHEET_COLUMNS = 2
SHEET_GAP_PX = 2  # between the frames, in the sheet's dark
SHEET_BACK = (20, 16, 32)


def places_sheet(path: Path) -> None:
    """The shipped levels, one frame each, captioned ``N. Title (setting)``."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    assets = load_assets()
    levels = sorted(LEVELS_DIR.glob("*.tmx"))
    rows = -(-len(levels) // SHEET_COLUMNS)
    sheet = pygame.Surface((SHEET_COLUMNS * (VIEW_W_PX + SHEET_GAP_PX) + SHEET_GAP_PX,
                            rows * (VIEW_H_PX + SHEET_GAP_PX) + SHEET_GAP_PX))
    sheet.fill(SHEET_BACK)
    for number, level in enumerate(levels):
        script = input_script(ROOT / "tests" / "scripts" / f"{level.stem}.txt")
        campaign = Campaign(level, loader=lambda p: load_level(p, images=True))
        while campaign.ticks < PLACES_TICK and not campaign.results:
            campaign.tick(script.held_at(campaign.ticks))
        frame = render_frame(campaign, debug=False, assets=assets).copy()
        world = campaign.world.level
        caption = f"{number + 1}. {world.title} ({place_of(world.properties).name})"
        draw_text(frame, assets.font, caption, (VIEW_W_PX // 2, VIEW_H_PX - 4),
                  anchor="midbottom")
        row, col = divmod(number, SHEET_COLUMNS)
        sheet.blit(frame, (SHEET_GAP_PX + col * (VIEW_W_PX + SHEET_GAP_PX),
                           SHEET_GAP_PX + row * (VIEW_H_PX + SHEET_GAP_PX)))
    save_image(sheet, path)
    pygame.display.quit()


MENUS_FRAME = 40  # the title sky's animation frame in the picture of the menus
MENUS_LEVELS_DONE = 2  # levels finished, each by its winning script, in that picture


def menus_picture(path: Path) -> None:
    """The options screen (the game speed row lit) beside the level select, for a player who
    has finished the first levels by their winning scripts."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    assets = load_assets()
    levels = campaign_levels(FIRST_LEVEL)
    progress = Progress()
    for info in levels[:MENUS_LEVELS_DONE]:
        script = input_script(ROOT / "tests" / "scripts" / f"{info.path.stem}.txt")
        campaign = Campaign(info.path, loader=lambda p: load_level(p, images=False))
        while not campaign.results:
            campaign.tick(script.held_at(campaign.ticks))
        result = campaign.results[-1]
        following = campaign.world.level.path if campaign.world.level.path != info.path else None
        progress.complete_level(info.path.name, result.ticks, result.coins,
                                None if following is None else following.name)
    sheet = pygame.Surface((2 * VIEW_W_PX + 3 * SHEET_GAP_PX, VIEW_H_PX + 2 * SHEET_GAP_PX))
    sheet.fill(SHEET_BACK)
    frame = pygame.Surface((VIEW_W_PX, VIEW_H_PX))
    settings = Settings(game_speed=80)
    draw_options(frame, assets, MENUS_FRAME, settings, OPTION_ITEMS.index(GAME_SPEED))
    sheet.blit(frame, (SHEET_GAP_PX, SHEET_GAP_PX))
    draw_level_select(frame, assets, MENUS_FRAME, level_entries(levels, progress),
                      MENUS_LEVELS_DONE)
    sheet.blit(frame, (2 * SHEET_GAP_PX + VIEW_W_PX, SHEET_GAP_PX))
    save_image(sheet, path)
    pygame.display.quit()


ENDINGS_LEVEL = LEVELS_DIR / "05-spike-gauntlet.tmx"  # the level that brings in checkpoints
LANTERN_FLARE_TICKS = 8  # how long after the lantern lights its frame is taken
LOSING_LEVEL = LEVELS_DIR / "03-hop-along.tmx"  # holding right meets its frogs, three times
LOSING_MAX_TICKS = 3600  # a minute of holding right: the picture is refused if no end by then
CREDITS_SHOWN_S = 9  # how far into the roll the credits' frame is taken


def endings_sheet(path: Path) -> None:
    """Three frames side by side: a checkpoint's lantern just lit in Spike Gauntlet (its
    winning script), game over with Retry this level lit (Hop Along, holding right until
    the last life is lost) and the credits nine seconds into their roll."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    assets = load_assets()
    renderer = WorldRenderer(assets)
    renderer.effects = Effects()
    script = input_script(ROOT / "tests" / "scripts" / f"{ENDINGS_LEVEL.stem}.txt")
    campaign = Campaign(ENDINGS_LEVEL, loader=lambda p: load_level(p, images=True))
    lit_at = None
    while lit_at is None or campaign.ticks < lit_at + LANTERN_FLARE_TICKS:
        world = campaign.world
        events = campaign.tick(script.held_at(campaign.ticks))
        renderer.effects.observe(world, events)
        renderer.effects.advance(TICK_S)
        if lit_at is None and any(e.kind is EventKind.CHECKPOINT for e in events):
            lit_at = campaign.ticks
    frames = [render_frame(campaign, debug=False, renderer=renderer).copy()]
    losing = Campaign(LOSING_LEVEL, loader=lambda p: load_level(p, images=True))
    while losing.outcome is Outcome.RUNNING and losing.ticks < LOSING_MAX_TICKS:
        losing.tick(frozenset({Action.RIGHT}))
    if losing.outcome is not Outcome.GAME_OVER:
        raise RuntimeError(f"{LOSING_LEVEL.name}: holding right no longer loses every life "
                           f"in {LOSING_MAX_TICKS} ticks: choose another LOSING_LEVEL")
    frame = render_frame(losing, debug=False, assets=assets).copy()
    draw_game_over(frame, assets, losing, GAME_OVER_ITEMS.index(RETRY))
    frames.append(frame)
    frame = pygame.Surface((VIEW_W_PX, VIEW_H_PX))
    draw_credits(frame, assets, CREDITS_SHOWN_S * ANIMATION_HZ)
    frames.append(frame)
    sheet = pygame.Surface((len(frames) * (VIEW_W_PX + SHEET_GAP_PX) + SHEET_GAP_PX,
                            VIEW_H_PX + 2 * SHEET_GAP_PX))
    sheet.fill(SHEET_BACK)
    for number, frame in enumerate(frames):
        sheet.blit(frame, (SHEET_GAP_PX + number * (VIEW_W_PX + SHEET_GAP_PX), SHEET_GAP_PX))
    save_image(sheet, path)
    pygame.display.quit()


def main() -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    for shot in SHOTS_TO_TAKE:
        command = shot.command()
        print(" ".join(["python", *command[1:]]))
        subprocess.run(command, cwd=ROOT, check=True)
    print("level-end.png: the first level's winning script, drawn with the banner")
    level_end_picture(SHOTS / "level-end.png")
    print(f"debug-full-panel.png: the same script to tick {FULL_PANEL_TICKS}, with the "
          "overlay's full panel (F5)")
    full_panel_picture(SHOTS / "debug-full-panel.png")
    print(f"places.png: each shipped level at tick {PLACES_TICK} of its winning script")
    places_sheet(SHOTS / "places.png")
    print(f"menus.png: the options and the level select after {MENUS_LEVELS_DONE} levels")
    menus_picture(SHOTS / "menus.png")
    print("endings.png: a lantern just lit, game over with Retry this level, the credits")
    endings_sheet(SHOTS / "endings.png")


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
