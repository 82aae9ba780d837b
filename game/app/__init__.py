"""The program around the simulation: command line, window, drawing, sound, menus and files.

:mod:`~game.app.cli` parses ``python -m game``; :mod:`~game.app.run` steps a run headless and
writes its report; :mod:`~game.app.window` is the interactive loop, drawing each frame with
:mod:`~game.app.frame` (world, HUD, debug overlay). Everything here reads the simulation and
feeds it actions; nothing here changes where a body ends up.
"""
