"""The simulation: a headless, deterministic platformer that never touches the display.

One tick reads top to bottom in :meth:`game.sim.world.World.step`; the swept x and y passes
are the reference's (:mod:`game.collision.axis_sweep`), against the level's tiles and moving
platforms asked as one (:mod:`~game.sim.solids`). Bodies,
the player, enemies, pickups and platforms are entities that set velocities; only movement
changes positions. Each of them is a sprite (:mod:`~game.sim.sprite`) whose drawn ``rect``
follows its float box; the app only hands it pictures. :mod:`~game.sim.campaign` plays
levels in order; it is given a loader, so
the simulation never imports the Tiled loader or the app above it.
"""
