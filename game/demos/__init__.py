"""Demos beside the game: scenes with more movers than a level, where a broad phase pays.

:mod:`~game.demos.crates` pushes crates apart with :mod:`game.collision.response`;
:mod:`~game.demos.stress` (``python -m game.demos.stress``) runs thousands of them and shows the
broad phase that :mod:`game.collision.methods` picks for each crowd.
"""
