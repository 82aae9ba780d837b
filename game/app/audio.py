"""Play the sound effects, the jingles and the music, or stay quietly silent without a sound card.

Where it sits: beside the renderer, above the simulation. After each tick the window hands
the tick's events to :meth:`Audio.play`; like drawing, playing a sound only reads what the
tick left behind and never changes the game. The sounds are made by :mod:`game.tools.synth`.

What it teaches:
  * **Effects are Sounds, music is streamed.** A ``pygame.mixer.Sound`` is decoded into
    memory once and can play on several channels at once (coins in quick succession); the
    jingles (a checkpoint, a clear, game over, the win) are Sounds too. ``pygame.mixer.music``
    decodes one long file as it plays, and loops it: one track at a time, the title's or the
    place's (:data:`MUSIC_TRACKS`), and asking for another swaps it. Both are handed
    bytes read once through the one bounded open
    (:func:`game.app.files.read_small_bytes`), never a path to open themselves.
  * **Sound is optional.** A machine with no audio device, a headless run or a missing file
    gives a silent :class:`Audio` whose methods do nothing; :attr:`Audio.status` says why,
    in one sentence, for the caller to show or ignore. Nothing is raised and nothing printed.
  * **C libraries talk on descriptor 2.** When SDL probes a missing sound card, ALSA prints
    from C straight to the process's stderr, out of reach of ``sys.stderr``; the mixer is
    opened with descriptor 2 pointed at the null device so a silent game stays quiet.

>>> audio = Audio(enabled=False)
>>> audio.silent, audio.status
(True, 'Sound is off.')
>>> audio.play("coin")  # does nothing, and says nothing
>>> audio.play("coins")
Traceback (most recent call last):
    ...
ValueError: no sound is called 'coins': use one of jump, coin, stomp, hurt, menu, tally, \
checkpoint, clear, game-over, win
"""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pygame

from game.app.files import FileProblem, read_small_bytes
from game.app.places import PLACES
from game.levels.shipped import ASSETS_DIR
from game.sim.world import EventKind

ASSETS = ASSETS_DIR
SOUNDS = ASSETS / "sounds"

# <name>.wav in SOUNDS; "tally" plays when the level-end banner's tally is up, "game-over"
# and "win" when the run ends
EFFECT_NAMES = ("jump", "coin", "stomp", "hurt", "menu", "tally",
                "checkpoint", "clear", "game-over", "win")
TITLE_TRACK = "title"  # the menus' music; each place's track is named after the place
MUSIC_TRACKS = (TITLE_TRACK, *PLACES)  # music-<track>.wav in SOUNDS, each a loop


def music_file(track: str) -> str:
    """The file a music track is read from.

    >>> music_file("caves")
    'music-caves.wav'
    """
    return f"music-{track}.wav"


MAX_SOUND_BYTES = 16 * 1024 * 1024  # each sound of the game's own: a music loop is about 350 kB
SOUND_FOR_EVENT: dict[EventKind, str] = {  # events missing here make no sound
    EventKind.JUMP: "jump",
    EventKind.COIN: "coin",
    EventKind.STOMP: "stomp",
    EventKind.HURT: "hurt",
    EventKind.EXIT: "clear",
    EventKind.CHECKPOINT: "checkpoint",
}

MIXER_RATE_HZ = 44100
MIXER_CHANNELS = 2  # stereo output; the mono sounds play in both ears
MIXER_BUFFER_SAMPLES = 512  # about 12 ms: short enough that a jump sounds with its jump
SAMPLE_BITS = -16  # signed 16-bit samples, pygame's spelling


@contextmanager
def quiet_native_stderr() -> Iterator[None]:
    """Point file descriptor 2 at the null device for the duration of the ``with`` block.

    Where descriptor 2 cannot be duplicated (no console at all), it is left alone.
    """
    if sys.stderr is not None:
        sys.stderr.flush()
    try:
        saved = os.dup(2)
    except OSError:
        saved = -1
    if saved < 0:
        yield
        return
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(null, 2)
            yield
        finally:
            os.dup2(saved, 2)
            os.close(null)
    finally:
        os.close(saved)


class Audio:
    """The game's speakers: :meth:`play` an effect, :meth:`start_music` (a track by name),
    :meth:`set_volume`.

    ``enabled=False`` (headless runs) never touches the mixer. Otherwise the mixer is opened
    if it is not open already; if it cannot be, the object is silent and :attr:`status`
    says why. A missing or broken file silences only that sound.
    """

    def __init__(self, sounds: Path = SOUNDS, *, enabled: bool = True) -> None:
        self.status = "Sound is on."
        self._effects: dict[str, pygame.mixer.Sound] = {}
        self._tracks: dict[str, bytes] = {}  # each music file, decoded as it plays
        self._track: str | None = None  # the track the mixer has, playing or paused
        self._music_stream: io.BytesIO | None = None  # what the mixer reads it from
        self._music_paused = False
        self._opened_mixer = False
        self._effects_volume = 1.0
        self._music_volume = 1.0
        if not enabled:
            self.status = "Sound is off."
            return
        try:
            if not pygame.mixer.get_init():
                with quiet_native_stderr():
                    pygame.mixer.init(MIXER_RATE_HZ, SAMPLE_BITS, MIXER_CHANNELS,
                                      MIXER_BUFFER_SAMPLES)
                self._opened_mixer = True
        except (pygame.error, NotImplementedError) as error:  # no device; no mixer module
            self.status = f"Sound is off: no audio device could be opened ({error})."
            return
        missing = self._load(sounds)
        if missing:
            self.status = (f"Some sounds are missing or unreadable ({', '.join(missing)} "
                           f"in {sounds}): run python -m game.tools.synth to make them.")

    def _load(self, sounds: Path) -> list[str]:
        """Load every effect and read every track; return the names of files that failed."""
        missing: list[str] = []
        for name in EFFECT_NAMES:
            path = sounds / f"{name}.wav"
            try:
                data = read_small_bytes(path, MAX_SOUND_BYTES, "the sound")
                self._effects[name] = pygame.mixer.Sound(file=io.BytesIO(data))
            except (pygame.error, FileProblem):  # a broken file; a missing one
                missing.append(path.name)
        for track in MUSIC_TRACKS:
            path = sounds / music_file(track)
            try:
                self._tracks[track] = read_small_bytes(path, MAX_SOUND_BYTES, "the music")
            except FileProblem:
                missing.append(path.name)
        self._apply_volumes()
        return missing

    @property
    def silent(self) -> bool:
        """True when no sound at all can play."""
        return not self._effects and not self._tracks

    def play(self, sound: EventKind | str) -> None:
        """Play an effect by name (``"menu"``) or for a world event (``EventKind.COIN``).

        Events without a sound are ignored; an unknown name is a bug in the caller and
        raises :class:`ValueError`, even when silent, so tests catch it.
        """
        if isinstance(sound, EventKind):
            name = SOUND_FOR_EVENT.get(sound)
            if name is None:
                return
        elif sound in EFFECT_NAMES:
            name = sound
        else:
            raise ValueError(f"no sound is called {sound!r}: use one of "
                             f"{', '.join(EFFECT_NAMES)}")
        effect = self._effects.get(name)
        if effect is not None:
            effect.play()

    @property
    def track(self) -> str | None:
        """The track last started and not stopped since (playing or paused), if any."""
        return self._track

    def start_music(self, track: str = TITLE_TRACK) -> None:
        """Loop ``track``: resume it if paused, start it if stopped or if another track
        is on, else leave it be. A track that cannot be played leaves the music silent."""
        if track not in MUSIC_TRACKS:
            raise ValueError(f"no music is called {track!r}: use one of "
                             f"{', '.join(MUSIC_TRACKS)}")
        music = self._tracks.get(track)
        if music is None:
            self.stop_music()
            return
        if track == self._track and self._music_paused:
            pygame.mixer.music.unpause()
            self._music_paused = False
            return
        if track == self._track and pygame.mixer.music.get_busy():
            return
        try:
            self._music_stream = io.BytesIO(music)  # kept while the mixer reads it
            pygame.mixer.music.load(self._music_stream, "wav")
            pygame.mixer.music.set_volume(self._music_volume)
            pygame.mixer.music.play(loops=-1)
            self._track, self._music_paused = track, False
        except pygame.error as error:
            del self._tracks[track]
            self._track = None
            self.status = f"The music {music_file(track)} could not be played ({error})."

    def pause_music(self) -> None:
        """Hold the music where it is; :meth:`start_music` carries on from there."""
        if self._track is not None and pygame.mixer.music.get_busy():
            pygame.mixer.music.pause()
            self._music_paused = True

    def stop_music(self) -> None:
        if self._track is not None:
            pygame.mixer.music.stop()
        self._track, self._music_paused = None, False

    def set_volume(self, effects: float, music: float) -> None:
        """Set both volumes, each from 0 (mute) to 1 (full); values outside are clamped."""
        self._effects_volume = min(1.0, max(0.0, effects))
        self._music_volume = min(1.0, max(0.0, music))
        self._apply_volumes()

    @property
    def volumes(self) -> tuple[float, float]:
        """The effects and music volumes, as last set."""
        return self._effects_volume, self._music_volume

    def _apply_volumes(self) -> None:
        for effect in self._effects.values():
            effect.set_volume(self._effects_volume)
        if self._tracks:
            pygame.mixer.music.set_volume(self._music_volume)

    def close(self) -> None:
        """Stop everything and close the mixer if this object opened it."""
        if self._opened_mixer and pygame.mixer.get_init():
            pygame.mixer.quit()
        self._effects.clear()
        self._tracks.clear()
        self._track = self._music_stream = None
        self._music_paused = False
        self._opened_mixer = False
