"""The collision reference: every technique a 2D game uses to find and resolve collisions.

Pure geometry with nothing of the game in it, so a reader can copy a module out whole. The
game runs :mod:`~game.collision.axis_sweep` (the swept x and y moves: read it first) against
:mod:`~game.collision.tile_grid` (the walls' lookup), over the shapes of
:mod:`~game.collision.shapes` and the boxes of :mod:`~game.collision.aabb` (strict overlap);
:mod:`~game.collision.free_place` gets a spawn out of a wall. The rest is taught, tested and
benchmarked beside them: :mod:`~game.collision.swept` (a whole move by slabs, which the
game does not run), :mod:`~game.collision.circles`, :mod:`~game.collision.sat`,
:mod:`~game.collision.masks` and :mod:`~game.collision.composite` (other shapes),
:mod:`~game.collision.response` (pushing apart), :mod:`~game.collision.contacts` (start and end
events) and the broad phases in :mod:`game.collision.broad`. :mod:`~game.collision.methods` says
which one a scene should use, from the benchmark's figures.
"""
