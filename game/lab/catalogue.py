"""The lab's scenes, in the order the list shows them, by group: the narrow phase (is this
pair touching?), the broad phase (which pairs are worth asking?), motion, response, and the
game's own coordinates and sprites.

Where it sits: read by :mod:`game.lab.cli` for ``--list``, ``--scene`` and the window's list,
and by the testbed for PageUp and PageDown. Adding a scene is one module under ``game/lab/``
and one line here, in its group.
"""

from __future__ import annotations

from game.lab.circle_precheck import CirclePrecheck
from game.lab.circles import Circles
from game.lab.composite import CompositeScene
from game.lab.contacts import Contacts
from game.lab.masks import Masks
from game.lab.overlap import Overlap
from game.lab.party_grid import PartyGrid
from game.lab.platformer import Platformer
from game.lab.polygons import Polygons
from game.lab.quadtree import QuadtreeScene
from game.lab.response import Response
from game.lab.rotated_box import RotatedBox
from game.lab.scene import Scene
from game.lab.screen_grid import ScreenGrid
from game.lab.sort_and_sweep import SortAndSweepScene
from game.lab.tunnelling import Tunnelling
from game.lab.xray import XRay

SCENES: tuple[type[Scene], ...] = (
    # narrow phase
    Overlap,
    RotatedBox,
    Polygons,
    Circles,
    CirclePrecheck,
    Masks,
    CompositeScene,
    # broad phase
    PartyGrid,
    QuadtreeScene,
    SortAndSweepScene,
    # motion
    Tunnelling,
    Platformer,
    # response
    Response,
    Contacts,
    # game
    ScreenGrid,
    XRay,
)
