"""Dust, squash and stretch, shake and pops: they answer events and change nothing in play."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pygame
import pytest

from game.app.assets import load_assets
from game.app.effects import (
    LANTERN_GLASS_ABOVE_FOOT_PX,
    RESPAWN_BEAT_S,
    SHAKE_S,
    SQUASH,
    STRETCH,
    Effects,
)
from game.app.render import WorldRenderer
from game.app.run import input_script
from game.collision.aabb import Box
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign
from game.sim.inputs import Action
from game.sim.tuning import TICK_S
from game.sim.world import EventKind
from tests.maps import level_from_ascii

SCRIPT = Path(__file__).resolve().parent / "scripts" / f"{FIRST_LEVEL.stem}.txt"
TICKS = 700  # far into the first level: jumps, landings, coins and both stomps


@pytest.fixture
def screen() -> pygame.Surface:
    pygame.display.init()
    return pygame.display.set_mode((320, 180))


def play(effects: Effects | None, screen: pygame.Surface | None = None
         ) -> tuple[Campaign, dict[EventKind, int]]:
    """The first level's winning script for :data:`TICKS` ticks, drawn every tick if asked."""
    script = input_script(SCRIPT)
    campaign = Campaign(FIRST_LEVEL, loader=lambda p: load_level(p, images=screen is not None))
    renderer = None
    if screen is not None:
        renderer = WorldRenderer(load_assets())
        renderer.effects = effects
    seen: dict[EventKind, int] = {}
    for _ in range(TICKS):
        world = campaign.world
        events = campaign.tick(script.held_at(campaign.ticks))
        for event in events:
            seen[event.kind] = seen.get(event.kind, 0) + 1
        if effects is not None:
            effects.observe(world, events)
            effects.advance(TICK_S)
        if renderer is not None and screen is not None:
            renderer.draw(screen, campaign.world, campaign.ticks)
    return campaign, seen


def test_effects_change_nothing_in_play(screen: pygame.Surface) -> None:
    plain, plain_events = play(None)
    juicy, juicy_events = play(Effects(), screen)
    assert juicy_events == plain_events
    assert juicy.world.player.box == plain.world.player.box
    assert (juicy.world.player.vx, juicy.world.player.vy) == (plain.world.player.vx,
                                                              plain.world.player.vy)
    assert (juicy.score, juicy.lives, juicy.ticks) == (plain.score, plain.lives, plain.ticks)


def test_each_event_leaves_its_effect() -> None:
    script = input_script(SCRIPT)
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    effects = Effects()
    answered = set()
    for _ in range(TICKS):
        world = campaign.world
        events = campaign.tick(script.held_at(campaign.ticks))
        effects.observe(world, events)
        kinds = {event.kind for event in events}
        if EventKind.JUMP in kinds:
            assert effects.squash == STRETCH and effects.particles
            answered.add("jump")
        if EventKind.STOMP in kinds:
            assert effects.shake_left_s == SHAKE_S and len(effects.particles) >= 10
            answered.add("stomp")
        if EventKind.COIN in kinds:
            assert effects.pops
            answered.add("coin")
        if effects.squash == SQUASH and effects.squash_left_s > 0:
            answered.add("landing")
        effects.advance(TICK_S)
    assert answered == {"jump", "stomp", "coin", "landing"}
    effects.advance(1.0)
    assert not effects.particles and not effects.pops and effects.scale_now() == (1.0, 1.0)


def test_a_squashed_picture_keeps_its_feet_on_the_box(screen: pygame.Surface) -> None:
    campaign = Campaign(FIRST_LEVEL, loader=lambda p: load_level(p, images=True))
    renderer = WorldRenderer(load_assets())
    renderer.draw(screen, campaign.world, 0)
    player = campaign.world.player
    plain = player.rect.copy()
    effects = renderer.effects = Effects()
    effects.observe(campaign.world, [])
    effects._start_squash(SQUASH)
    box = player.box
    renderer.draw(screen, campaign.world, 0)
    assert player.box == box
    assert player.rect.w > plain.w and player.rect.h < plain.h
    assert player.rect.bottom == plain.bottom and abs(player.rect.centerx - plain.centerx) <= 1


@pytest.mark.parametrize("shake_on", [True, False])
def test_the_shake_swings_the_world_under_a_still_sky_and_smears_nothing(
        screen: pygame.Surface, monkeypatch: pytest.MonkeyPatch, shake_on: bool) -> None:
    """A shaken frame is the world drawn again from a camera a few pixels off, every pixel
    of it fresh: not the last frame scrolled, which leaves its edge behind."""
    monkeypatch.setattr(WorldRenderer, "_draw_sky",
                        lambda self, target, world: target.fill((0, 0, 0)))
    campaign = Campaign(FIRST_LEVEL, loader=lambda p: load_level(p, images=True))
    world = campaign.world
    world.camera.x, world.camera.y = 200.0, 40.0
    assets = load_assets()
    shaking = WorldRenderer(assets)
    shaking.effects = Effects(shake_on=shake_on, shake_left_s=SHAKE_S)
    dx, dy = shaking.effects.shake_offset()
    assert (dx, dy) != (0, 0) if shake_on else (dx, dy) == (0, 0)
    screen.fill((255, 0, 255))        # what a scroll would leave behind at the edge
    shaking.draw(screen, world, 0)
    shaken = pygame.image.tobytes(screen, "RGB")
    world.camera.x, world.camera.y = 200.0 - dx, 40.0 - dy
    WorldRenderer(assets).draw(screen, world, 0)
    assert shaken == pygame.image.tobytes(screen, "RGB")


def test_a_lit_lantern_glows_and_a_respawn_gathers_light_on_the_hero_changing_nothing() -> None:
    """Walk right through a checkpoint's lantern into spikes: the lantern glows as it lights,
    and the ring that answers the hurt closes in on where the hero comes back."""
    rows = ["              ", " P   ^^^^^^^^ ", "##############"]
    level = dataclasses.replace(level_from_ascii(rows), checkpoints=(Box(48, 0, 16, 32),))
    plain, juicy = Campaign(level.path, loader=lambda _: level), Campaign(
        level.path, loader=lambda _: level)
    effects = Effects()
    glows = beats = 0
    for _ in range(120):
        plain_events = plain.tick(frozenset({Action.RIGHT}))
        world = juicy.world
        events = juicy.tick(frozenset({Action.RIGHT}))
        assert events == plain_events and world.player.box == plain.world.player.box
        effects.observe(world, events)
        kinds = {event.kind for event in events}
        if EventKind.CHECKPOINT in kinds:
            ring = effects.rings[-1]
            assert ring.radius_px[0] < ring.radius_px[1]  # grows out of the lantern
            assert ring.x == 56 and ring.y == 32 - LANTERN_GLASS_ABOVE_FOOT_PX
            glows += 1
        if EventKind.HURT in kinds:
            ring = effects.rings[-1]
            box = world.player.box  # back at the lantern
            assert ring.radius_px[0] > ring.radius_px[1]  # closes in on the hero
            assert (ring.x, ring.y) == (box.x + box.w / 2, box.y + box.h / 2)
            assert ring.life_s == RESPAWN_BEAT_S
            beats += 1
        effects.advance(TICK_S)
    assert glows == 1 and beats >= 1
    effects.advance(RESPAWN_BEAT_S)
    assert not effects.rings
