"""The programs that make the project's assets from code, so every picture and sound is ours.

``python -m game.tools.art`` draws the tileset and sprites, ``python -m game.tools.synth``
synthesises the sounds and music, and ``python -m game.tools.screenshots`` remakes the README's
pictures from the game itself.
"""
