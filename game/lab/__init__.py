"""The collision lab: every technique of the collision reference as a scene you can touch.

``python -m game.lab`` opens a window with the list of scenes; ``--scene NAME`` opens one,
``--list`` prints their names and ``--scene NAME --screenshot PNG`` draws one without a window.

Where it sits: a program beside the game, like the demos and the bench. It imports the
collision reference (and the simulation's tile grid and movement, for the platformer scene)
and only draws what those functions answer; the game never imports the lab, so it adds
nothing to a tick.

What it teaches: each scene is one module (``overlap``, ``rotated_box``, ``tunnelling``, ...)
built on a small framework (:mod:`~game.lab.scene`, :mod:`~game.lab.testbed`). Where a cheaper
method sits beside an exact one, the scene times both live (:mod:`~game.lab.cost`) and marks
where the cheaper one is wrong.
"""
