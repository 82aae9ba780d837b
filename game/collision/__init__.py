"""The collision reference: every technique a 2D game uses to find and resolve collisions.

Pure geometry with nothing of the game in it, so a reader can copy a module out whole. Read
:mod:`~game.collision.aabb` first (boxes and strict overlap), then :mod:`~game.collision.swept`
(stopping fast movers), :mod:`~game.collision.circles`, :mod:`~game.collision.sat`,
:mod:`~game.collision.masks` and :mod:`~game.collision.composite` (other shapes),
:mod:`~game.collision.response` (pushing apart), :mod:`~game.collision.contacts` (start and end
events) and the broad phases in :mod:`game.collision.broad`. :mod:`~game.collision.methods` says
which one a scene should use, from the benchmark's figures.
"""
