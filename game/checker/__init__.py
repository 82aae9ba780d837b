"""The level checker: is a map that loads one a designer meant, and can it be won?

Where it sits: beside :mod:`game.app`, above the loader (:mod:`game.levels`), whose level it
judges; nothing in the loader or the game imports it. ``python -m game.levels check`` and
``solve`` run it (:mod:`game.checker.cli`), and so do the Tiled project's Check command and
extension. The level designer's guide (``levels/README.md``) tells what each finding means.

Its parts, in the order a check runs them:

* :mod:`~game.checker.cli`: the command line: ``check``, ``solve``, ``reach`` and ``types``.
* :mod:`~game.checker.checking`: check one map: the loader's findings, the designer checks,
  then the verdict, as lines or JSON.
* :mod:`~game.checker.side_by_side`: several maps one per core, reports in order.
* :mod:`~game.checker.designer_checks` and :mod:`~game.checker.tile_mistakes`: mistakes a map
  loads with but a designer would not mean (a platform's path through a wall, a coin no jump
  reaches, planks upside down, ground with no class, walls on a decoration layer...);
  :mod:`~game.checker.wall_layers`: which layer's tiles close the way.
* :mod:`~game.checker.verdict`: solved, impossible or not decided, and nothing else.
* The proofs of impossible: :mod:`~game.checker.reachable` (a generous flood fill of all the
  player could touch, every mechanic bounded) and :mod:`~game.checker.jump_envelope` (the
  pixel-exact reach, exact at the measured limits, kept clear of where every enemy and
  moving platform can be: :mod:`~game.checker.mechanic_bounds`), both from
  :mod:`~game.checker.reach` (how high and far the player jumps, measured in the game's own
  tick).
* The search for a win: :mod:`~game.checker.solver` (the game's own tick, searched),
  :mod:`~game.checker.search_budget` (the moves a map may take, growing with the map),
  :mod:`~game.checker.search_key` (when two states are the same) and
  :mod:`~game.checker.enemy_timeline` (enemies far from the player, put back where they walk).
* :mod:`~game.checker.route_picture`: a route drawn over the map.
"""
