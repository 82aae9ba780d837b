"""Broad phases: find the few pairs worth an exact test among many movers.

:mod:`~game.collision.broad.brute_force` states the contract (``add``, ``remove``, ``move``,
``pairs``, ``query``) and tests every pair; :mod:`~game.collision.broad.spatial_grid`,
:mod:`~game.collision.broad.quadtree` and :mod:`~game.collision.broad.sort_and_sweep` are three
ways to test fewer, each exact against the brute-force answer.
"""
