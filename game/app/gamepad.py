"""Gamepads: the stick, the d-pad and the buttons, turned into actions and menu moves.

Where it sits: beside the keyboard in step 1 of a tick. Each tick the window asks
:class:`Gamepads` what the pads hold and plays the union of that and the keyboard; between
ticks it turns pad events into menu moves (:class:`game.app.menus.Nav`) with :func:`pad_nav`.
Everything but :class:`Gamepads` is pure: the tests feed it numbers and synthetic events.

What it teaches:
  * **pygame.joystick is the portable API.** Upstream pygame 2.6 also ships an experimental
    ``pygame._sdl2.controller`` (SDL's GameController, with named buttons), but it is private
    and may change; the plain joystick module works everywhere and is enough here.
  * **Hot-plug by events.** Pads come and go with ``JOYDEVICEADDED`` (which names a *device
    index*) and ``JOYDEVICEREMOVED`` (which names an *instance id*, the number every later
    event of that pad carries). Pads plugged in before the game starts arrive the same way,
    so one code path handles both.
  * **A dead zone.** A stick at rest rarely reads exactly 0; anything inside
    :data:`STICK_DEAD_ZONE` counts as centred, so a worn stick does not walk the hero.
  * **Hysteresis for menus.** A stick sends a stream of axis events as it moves. A menu
    moves once when the stick is pushed past :data:`STICK_MENU_PUSH` and not again until it
    has come back inside the dead zone (:class:`StickEdges`), so one flick is one step.

Button numbers are SDL's for an Xbox-style pad read through the joystick API (on Linux,
Windows and macOS alike): 0 A, 1 B, 2 X, 3 Y, 4 LB, 5 RB, 6 Back, 7 Start. Other pads
number their buttons differently; the play bindings come from ``Settings.buttons``.

>>> sorted(a.value for a in stick_actions(0.9, -0.1))
['right']
>>> sorted(a.value for a in hat_actions((-1, 1)))
['left', 'up']
>>> pad_nav(pygame.event.Event(pygame.JOYBUTTONDOWN, button=BUTTON_A, instance_id=0),
...         StickEdges(), playing=False)
<Nav.CONFIRM: 'confirm'>
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import NamedTuple, Protocol

import pygame

from game.app.menus import Nav
from game.sim.inputs import NOTHING, Action, Actions

STICK_DEAD_ZONE = 0.25  # fraction of full tilt: a stick nearer centre than this is centred
STICK_MENU_PUSH = 0.6  # fraction of full tilt that counts as one step in a menu
STICK_X_AXIS = 0  # the left stick, as SDL numbers the axes: x is -1 left to +1 right
STICK_Y_AXIS = 1  # ... and y is -1 up to +1 down (the opposite of the hat's y)
DPAD_HAT = 0  # the d-pad is the first hat: (x, y) with x -1 left, y +1 up

BUTTON_A = 0  # confirm in menus (and jump, by the default Settings.buttons)
BUTTON_B = 1  # back in menus
BUTTON_START = 7  # pause and resume

NAV_FOR_BUTTON: dict[int, Nav] = {BUTTON_A: Nav.CONFIRM, BUTTON_B: Nav.BACK,
                                  BUTTON_START: Nav.PAUSE}


class PadReading(NamedTuple):
    """What one pad holds at one moment: the left stick, the d-pad, the buttons down."""

    stick: tuple[float, float] = (0.0, 0.0)
    hat: tuple[int, int] = (0, 0)
    buttons: frozenset[int] = frozenset()


def stick_actions(x: float, y: float, dead_zone: float = STICK_DEAD_ZONE) -> Actions:
    """The directions a stick at (``x``, ``y``) pushes; inside the dead zone, none.

    >>> stick_actions(0.2, -0.2) == NOTHING
    True
    >>> sorted(a.value for a in stick_actions(-1.0, 1.0))
    ['down', 'left']
    """
    held: set[Action] = set()
    if x < -dead_zone:
        held.add(Action.LEFT)
    elif x > dead_zone:
        held.add(Action.RIGHT)
    if y < -dead_zone:
        held.add(Action.UP)
    elif y > dead_zone:
        held.add(Action.DOWN)
    return frozenset(held)


def hat_actions(hat: tuple[int, int]) -> Actions:
    """The directions a d-pad (a hat, ``(x, y)`` with y +1 up) is pressed towards."""
    x, y = hat
    held: set[Action] = set()
    if x:
        held.add(Action.LEFT if x < 0 else Action.RIGHT)
    if y:
        held.add(Action.UP if y > 0 else Action.DOWN)
    return frozenset(held)


def button_actions(pressed: Iterable[int], bindings: Mapping[Action, tuple[int, ...]]) -> Actions:
    """The actions with at least one of their buttons in ``pressed``.

    >>> sorted(a.value for a in button_actions({0, 5}, {Action.JUMP: (0,), Action.LEFT: ()}))
    ['jump']
    """
    down = set(pressed)
    return frozenset(action for action, buttons in bindings.items() if down.intersection(buttons))


def pad_actions(pad: PadReading, bindings: Mapping[Action, tuple[int, ...]]) -> Actions:
    """Everything one pad holds: stick, d-pad and bound buttons together."""
    return stick_actions(*pad.stick) | hat_actions(pad.hat) | button_actions(pad.buttons, bindings)


class StickEdges:
    """Turns a stream of stick positions into single pushes, per pad and axis.

    >>> edges = StickEdges()
    >>> [edges.push(0, STICK_Y_AXIS, y) for y in (0.3, 0.7, 0.9, 0.4, 0.1, 0.8)]
    [0, 1, 0, 0, 0, 1]
    """

    def __init__(self) -> None:
        self._pushed: dict[tuple[int, int], int] = {}  # (instance id, axis) -> -1, 0 or +1

    def push(self, instance_id: int, axis: int, value: float) -> int:
        """-1 or +1 when this reading newly pushes the axis that way; 0 otherwise."""
        key = (instance_id, axis)
        was = self._pushed.get(key, 0)
        if abs(value) < STICK_DEAD_ZONE:
            self._pushed[key] = 0
            return 0
        if was or abs(value) < STICK_MENU_PUSH:
            return 0  # still held from before, or not pushed far enough yet
        self._pushed[key] = 1 if value > 0 else -1
        return self._pushed[key]

    def forget(self, instance_id: int) -> None:
        """Drop what is remembered about a pad that was unplugged."""
        self._pushed = {key: way for key, way in self._pushed.items() if key[0] != instance_id}


def pad_nav(event: pygame.event.Event, edges: StickEdges, *, playing: bool) -> Nav | None:
    """The menu move a pad event makes, if any.

    While playing, the pad's buttons belong to the game: only Start reaches the menus, and a
    pad pulled out mid-play pauses. In menus, A confirms, B goes back, Start pauses or
    resumes, and the d-pad or the stick moves up and down.
    """
    if event.type == pygame.JOYDEVICEREMOVED:
        edges.forget(event.instance_id)
        return Nav.PAUSE if playing else None
    nav: Nav | None = None
    if event.type == pygame.JOYBUTTONDOWN:
        nav = NAV_FOR_BUTTON.get(event.button)
    elif event.type == pygame.JOYHATMOTION and event.hat == DPAD_HAT:
        nav = _vertical(event.value[1])
    elif event.type == pygame.JOYAXISMOTION and event.axis == STICK_Y_AXIS:
        # Read even in play, so the edges know where the stick is when a menu opens.
        nav = _vertical(-edges.push(event.instance_id, event.axis, event.value))
    if playing and nav is not Nav.PAUSE:
        return None
    return nav


def pad_in_use(event: pygame.event.Event, was: bool) -> bool:
    """Whether the player is using a pad, after ``event``: a key press says no, a pad's
    button or d-pad says yes, anything else leaves ``was``. Screens show that device's
    controls."""
    if event.type == pygame.KEYDOWN:
        return False
    if event.type in (pygame.JOYBUTTONDOWN, pygame.JOYHATMOTION):
        return True
    return was


def _vertical(up: int) -> Nav | None:
    """UP for a positive ``up``, DOWN for a negative one, else None."""
    if up > 0:
        return Nav.UP
    return Nav.DOWN if up < 0 else None


class Joystick(Protocol):
    """What :func:`read_pad` asks of a pad: ``pygame.joystick.JoystickType``, or a test's
    stand-in with the same methods."""

    def get_numaxes(self) -> int: ...
    def get_axis(self, axis: int, /) -> float: ...
    def get_numhats(self) -> int: ...
    def get_hat(self, hat: int, /) -> tuple[float, float]: ...
    def get_numbuttons(self) -> int: ...
    def get_button(self, button: int, /) -> bool: ...


def read_pad(joystick: Joystick) -> PadReading:
    """What ``joystick`` holds now (a pad with no hat or a single axis reads as centred)."""
    axes = joystick.get_numaxes()
    stick = (joystick.get_axis(STICK_X_AXIS) if axes > STICK_X_AXIS else 0.0,
             joystick.get_axis(STICK_Y_AXIS) if axes > STICK_Y_AXIS else 0.0)
    hat_x, hat_y = joystick.get_hat(DPAD_HAT) if joystick.get_numhats() > DPAD_HAT else (0, 0)
    buttons = frozenset(b for b in range(joystick.get_numbuttons()) if joystick.get_button(b))
    return PadReading(stick, (int(hat_x), int(hat_y)), buttons)


class Gamepads:
    """The pads plugged in now, kept up to date by :meth:`handle`, read by :meth:`held`."""

    def __init__(self) -> None:
        pygame.joystick.init()  # pads already plugged in arrive as JOYDEVICEADDED events
        self.pads: dict[int, Joystick] = {}  # by instance id

    def handle(self, event: pygame.event.Event) -> None:
        """Open a pad that was plugged in; let go of one that was pulled out."""
        if event.type == pygame.JOYDEVICEADDED:
            joystick = pygame.joystick.Joystick(event.device_index)
            self.pads[joystick.get_instance_id()] = joystick
        elif event.type == pygame.JOYDEVICEREMOVED:
            self.pads.pop(event.instance_id, None)

    def held(self, bindings: Mapping[Action, tuple[int, ...]]) -> Actions:
        """The actions any pad holds now."""
        held = NOTHING
        for joystick in self.pads.values():
            held |= pad_actions(read_pad(joystick), bindings)
        return held
