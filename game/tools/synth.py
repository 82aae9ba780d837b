"""Synthesise the game's sound effects and its music loop from nothing but arithmetic.

Run from the repository root::

    python -m game.tools.synth

This (re)writes, in ``assets/sounds/`` next to the ``game`` package, six effects (``jump``,
``coin``, ``stomp``, ``hurt``, ``exit``, ``menu``) and ``music.wav``, a 12.8 s loop; all are
16-bit mono WAV files at 22050 Hz. Nothing is recorded or downloaded, so they are CC0 like
the art. Where it sits: a build step beside :mod:`game.tools.art`; the game only reads the files,
through :mod:`game.app.audio`.

What it teaches:
  * **A sound is a list of numbers**: 22050 samples a second, each from -1 to 1 while we
    work, scaled to 16-bit integers only when the file is written.
  * **An oscillator is a phase accumulator.** Each sample adds ``frequency / sample rate``
    to a phase counted in cycles, and the wave's shape is read from the fraction of a cycle.
    A pitch sweep only changes what is added, so the wave never jumps: no click.
  * **An envelope shapes loudness.** Every note rises from 0 and falls back to 0, so it
    starts and stops without a click, and a loop whose notes all end inside it joins up
    seamlessly.
  * **Deterministic by construction.** Samples are made with + - * / and ``floor`` only
    (no ``sin``, no ``pow``: those may differ in the last bit between C libraries) and noise
    comes from seeded generators, so every run on every machine writes the same bytes.

>>> [round(square(p), 1) for p in (0.0, 0.25, 0.5, 0.75)]
[1.0, 1.0, -1.0, -1.0]
>>> [triangle(p) for p in (0.0, 0.25, 0.5, 0.75)]
[0.0, 1.0, 0.0, -1.0]
>>> note_hz("A4"), note_hz("A5"), note_hz("C#3")
(440.0, 880.0, 138.59)
"""

from __future__ import annotations

import io
import math
import random
import sys
import wave
from array import array
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from enum import Enum

from game.app.files import write_bytes_atomically
from game.levels.closed_output import quiet_when_output_closes
from game.levels.shipped import ASSETS_DIR

ASSETS = ASSETS_DIR
SOUNDS = ASSETS / "sounds"

SAMPLE_RATE_HZ = 22050
SAMPLE_BYTES = 2  # 16-bit signed samples
FULL_SCALE = 32767  # the largest 16-bit sample: a sample of 1.0 is written as this

Samples = list[float]  # one float per sample, -1.0 to 1.0


# --------------------------------------------------------------------------
# Oscillators and envelopes
# --------------------------------------------------------------------------

class Wave(Enum):
    SQUARE = "square"  # hollow and bright: the classic chiptune voice
    TRIANGLE = "triangle"  # soft and round: bass lines and thuds
    NOISE = "noise"  # random steps: hats, snares and squishes


def square(phase: float, duty: float = 0.5) -> float:
    """A square wave: high for the first ``duty`` of each cycle, low for the rest."""
    return 1.0 if phase % 1.0 < duty else -1.0


def triangle(phase: float) -> float:
    """A triangle wave that starts at 0 and rises, so a note begins without a jump."""
    p = (phase + 0.25) % 1.0
    return 4.0 * p - 1.0 if p < 0.5 else 3.0 - 4.0 * p


@dataclass(frozen=True)
class Instrument:
    """How a voice sounds: its wave and its envelope. Units in the names."""

    wave: Wave
    volume: float = 0.5  # peak loudness, 0 to 1 of full scale
    attack_s: float = 0.004  # rise from silence to full volume
    release_s: float = 0.02  # fall back to silence at the end of the note
    sustain: float = 1.0  # loudness at the end relative to the start, before the release
    duty: float = 0.5  # square waves: the fraction of each cycle spent high


@dataclass(frozen=True)
class Tone:
    """One note on an instrument, with a pitch that may sweep from start to end."""

    instrument: Instrument
    start_hz: float  # for noise: how many times a second it picks a new random level
    end_hz: float  # equal to ``start_hz`` for a steady note
    duration_s: float


def samples_for(duration_s: float) -> int:
    """How many samples last ``duration_s`` seconds.

    >>> samples_for(0.2), samples_for(1.0)
    (4410, 22050)
    """
    return round(duration_s * SAMPLE_RATE_HZ)


def envelope(instrument: Instrument, n: int) -> list[float]:
    """The loudness of each of ``n`` samples: a linear attack, decay and release.

    It is 0 at the first sample and would be 0 again at sample ``n``, one past the end.

    >>> envelope(Instrument(Wave.SQUARE, volume=1.0, attack_s=2 / 22050, release_s=2 / 22050), 5)
    [0.0, 0.5, 1.0, 1.0, 0.5]
    """
    attack_n = max(1, samples_for(instrument.attack_s))
    release_n = max(1, samples_for(instrument.release_s))
    return [instrument.volume * min(1.0, i / attack_n) * min(1.0, (n - i) / release_n)
            * (1.0 + (instrument.sustain - 1.0) * i / n) for i in range(n)]


def render(tone: Tone, rng: random.Random) -> Samples:
    """Play one tone into a fresh list of samples; ``rng`` feeds the noise wave."""
    instrument = tone.instrument
    n = samples_for(tone.duration_s)
    out: Samples = []
    phase = 0.0
    level = rng.uniform(-1.0, 1.0) if instrument.wave is Wave.NOISE else 0.0
    for i, loudness in enumerate(envelope(instrument, n)):
        if instrument.wave is Wave.SQUARE:
            value = square(phase, instrument.duty)
        elif instrument.wave is Wave.TRIANGLE:
            value = triangle(phase)
        else:
            value = level
        out.append(value * loudness)
        hz = tone.start_hz + (tone.end_hz - tone.start_hz) * i / n
        next_phase = phase + hz / SAMPLE_RATE_HZ
        if instrument.wave is Wave.NOISE and math.floor(next_phase) != math.floor(phase):
            level = rng.uniform(-1.0, 1.0)  # a new cycle: noise jumps to a new level
        phase = next_phase
    return out


def mix(length: int, parts: Iterable[tuple[int, Samples]]) -> Samples:
    """Add each ``(offset, samples)`` part into ``length`` samples of silence.

    >>> mix(4, [(0, [0.5, 0.5]), (1, [0.25, 0.25, 0.25])])
    [0.5, 0.75, 0.25, 0.25]
    """
    out = [0.0] * length
    for offset, samples in parts:
        if offset + len(samples) > length:
            raise ValueError(f"a part of {len(samples)} samples at {offset} runs past the "
                             f"end ({length} samples): lengthen the sound or shorten the part")
        for i, value in enumerate(samples):
            out[offset + i] += value
    return out


def in_sequence(rng: random.Random, tones: Sequence[Tone]) -> Samples:
    """Play tones one after the other; each ends at silence, so they join without a click."""
    return [value for tone in tones for value in render(tone, rng)]


# --------------------------------------------------------------------------
# Notes by name: A4 is 440 Hz and each octave doubles
# --------------------------------------------------------------------------

OCTAVE_4_HZ = {  # equal temperament, to 0.01 Hz
    "C": 261.63, "C#": 277.18, "D": 293.66, "D#": 311.13, "E": 329.63, "F": 349.23,
    "F#": 369.99, "G": 392.00, "G#": 415.30, "A": 440.00, "A#": 466.16, "B": 493.88,
}


def note_hz(name: str) -> float:
    """The frequency of a note such as ``"C5"`` or ``"F#3"`` (sharps only, octaves 0-9)."""
    letter, octave = name[:-1], name[-1]
    if letter not in OCTAVE_4_HZ or not octave.isdigit():
        raise ValueError(f"{name!r} is not a note: write a letter A-G, an optional #, "
                         "then an octave 0-9, such as C5 or F#3")
    return math.ldexp(OCTAVE_4_HZ[letter], int(octave) - 4)  # exact doubling and halving


# --------------------------------------------------------------------------
# The sound effects: one small function each
# --------------------------------------------------------------------------

EFFECTS_SEED = 1987  # noise in the effects is the same on every run

JUMP = Tone(Instrument(Wave.SQUARE, volume=0.35, sustain=0.4),
            start_hz=280.0, end_hz=640.0, duration_s=0.14)
CHIME = Instrument(Wave.SQUARE, volume=0.3, release_s=0.005, sustain=0.9)
CHIME_RING = Instrument(Wave.SQUARE, volume=0.3, release_s=0.05, sustain=0.0)
COIN_NOTES = (("B5", 0.07), ("E6", 0.3))  # (note, seconds): a fourth up, the second rings
STOMP_THUD = Tone(Instrument(Wave.TRIANGLE, volume=0.6, attack_s=0.002, release_s=0.03,
                             sustain=0.3),
                  start_hz=190.0, end_hz=45.0, duration_s=0.16)
STOMP_SQUISH = Tone(Instrument(Wave.NOISE, volume=0.25, attack_s=0.002, sustain=0.0),
                    start_hz=3000.0, end_hz=600.0, duration_s=0.1)
BUZZ = Instrument(Wave.SQUARE, volume=0.22, attack_s=0.002, release_s=0.05, sustain=0.5,
                  duty=0.3)
HURT = Tone(BUZZ, start_hz=520.0, end_hz=130.0, duration_s=0.38)
HURT_DETUNE = 1.03  # a second voice this much sharper beats against the first: a buzz
BRASS = Instrument(Wave.SQUARE, volume=0.3, release_s=0.015, sustain=0.8)
FANFARE_NOTES = (("C5", 0.09), ("E5", 0.09), ("G5", 0.09), ("C6", 0.4))  # (note, seconds)
FANFARE_BASS = Tone(Instrument(Wave.TRIANGLE, volume=0.4, release_s=0.1, sustain=0.5),
                    note_hz("C4"), note_hz("C4"), duration_s=0.4)
TALLY_NOTES = (("G5", 0.05), ("A5", 0.05), ("B5", 0.05), ("D6", 0.05), ("G6", 0.35))
MENU = Tone(Instrument(Wave.SQUARE, volume=0.25, attack_s=0.001, release_s=0.01, sustain=0.3),
            start_hz=1800.0, end_hz=1200.0, duration_s=0.03)


def steady(instrument: Instrument, note: str, duration_s: float) -> Tone:
    """A note that holds its pitch, such as ``steady(BRASS, "C5", 0.09)``."""
    hz = note_hz(note)
    return Tone(instrument, hz, hz, duration_s)


def jump(rng: random.Random) -> Samples:
    """A rising square blip: the pitch climbs as the player does."""
    return render(JUMP, rng)


def coin(rng: random.Random) -> Samples:
    """A two-note chime: a short low note, then a ringing high one a fourth above."""
    (low, low_s), (high, high_s) = COIN_NOTES
    return in_sequence(rng, [steady(CHIME, low, low_s), steady(CHIME_RING, high, high_s)])


def stomp(rng: random.Random) -> Samples:
    """A thud (a falling triangle) under a squish (noise that slows down)."""
    thud = render(STOMP_THUD, rng)
    return mix(len(thud), [(0, thud), (0, render(STOMP_SQUISH, rng))])


def hurt(rng: random.Random) -> Samples:
    """A descending buzz: two slightly detuned square waves falling together."""
    sharp = Tone(BUZZ, HURT.start_hz * HURT_DETUNE, HURT.end_hz * HURT_DETUNE, HURT.duration_s)
    low = render(HURT, rng)
    return mix(len(low), [(0, low), (0, render(sharp, rng))])


def fanfare(rng: random.Random) -> Samples:
    """A little fanfare for the exit: a rising arpeggio landing on a held high C."""
    melody = in_sequence(rng, [steady(BRASS, note, s) for note, s in FANFARE_NOTES])
    bass = render(FANFARE_BASS, rng)
    return mix(len(melody), [(0, melody), (len(melody) - len(bass), bass)])


def tally(rng: random.Random) -> Samples:
    """The level-end tally: a quick climb of chimes, one a line, landing on a ringing G."""
    *climb, (last, last_s) = TALLY_NOTES
    return in_sequence(rng, [*(steady(CHIME, note, s) for note, s in climb),
                             steady(CHIME_RING, last, last_s)])


def menu(rng: random.Random) -> Samples:
    """A click: a very short, falling, high blip."""
    return render(MENU, rng)


# --------------------------------------------------------------------------
# The music: a lead and a bass read from a tiny score, plus drums
# --------------------------------------------------------------------------

MUSIC_SEED = 2024
TEMPO_BPM = 150
STEPS_PER_BEAT = 2  # one score token is an eighth note
STEP_S = 60.0 / TEMPO_BPM / STEPS_PER_BEAT  # 0.2 s
STEP_SAMPLES = samples_for(STEP_S)  # 4410: a whole number, so the steps never drift
LOOP_STEPS = 64  # 8 bars of 8 eighths: 12.8 s

# One token per step, "|" between bars: a note starts, "-" holds it, "." is silence.
# The chords are C, Am, F, G, twice; the last bar leads back to the first.
MELODY = """
E5 -  G5 -  C6 -  G5 -  | A5 -  -  -  E5 -  C5 -
F5 -  A5 -  C6 -  A5 -  | G5 -  -  -  B4 -  D5 -
E5 G5 C6 -  E6 -  D6 C6 | A5 -  C6 -  E6 -  C6 A5
F5 -  A5 C6 D6 -  C6 A5 | B5 -  D6 -  G5 -  .  .
"""
BASS = """
C3 C4 C3 C4 C3 C4 C3 C4 | A2 A3 A2 A3 A2 A3 A2 A3
F2 F3 F2 F3 F2 F3 F2 F3 | G2 G3 G2 G3 G2 G3 G2 G3
C3 C4 C3 C4 C3 C4 C3 C4 | A2 A3 A2 A3 A2 A3 A2 A3
F2 F3 F2 F3 F2 F3 F2 F3 | G2 G3 G2 G3 G2 G3 G2 G3
"""
DRUMS = " | ".join(["k h s h k h s h"] * 8)  # k kick, h hi-hat, s snare, . nothing

LEAD = Instrument(Wave.SQUARE, volume=0.2, release_s=0.03, sustain=0.55, duty=0.25)
BASS_VOICE = Instrument(Wave.TRIANGLE, volume=0.3, attack_s=0.003, sustain=0.7)
DRUM_KIT = {
    "k": Tone(Instrument(Wave.TRIANGLE, volume=0.3, attack_s=0.001, sustain=0.2),
              start_hz=150.0, end_hz=50.0, duration_s=0.1),
    "h": Tone(Instrument(Wave.NOISE, volume=0.08, attack_s=0.001, release_s=0.03, sustain=0.0),
              start_hz=9000.0, end_hz=9000.0, duration_s=0.04),
    "s": Tone(Instrument(Wave.NOISE, volume=0.12, attack_s=0.001, release_s=0.05, sustain=0.2),
              start_hz=4000.0, end_hz=2500.0, duration_s=0.12),
}


@dataclass(frozen=True)
class Note:
    step: int  # the score step it starts on
    steps: int  # how many steps it lasts
    name: str  # a note name, or a drum letter


def parse_score(score: str, steps: int = LOOP_STEPS) -> list[Note]:
    """Read a score: one token per step, ``-`` holds the last note, ``.`` rests.

    >>> parse_score("C4 - . | E4", 4)
    [Note(step=0, steps=2, name='C4'), Note(step=3, steps=1, name='E4')]
    >>> parse_score("C4 -", 3)
    Traceback (most recent call last):
        ...
    ValueError: the score has 2 steps, expected 3: every voice must fill the loop exactly
    """
    tokens = score.replace("|", " ").split()
    if len(tokens) != steps:
        raise ValueError(f"the score has {len(tokens)} steps, expected {steps}: "
                         "every voice must fill the loop exactly")
    notes: list[Note] = []
    for step, token in enumerate(tokens):
        if token == "-":
            if not notes or notes[-1].step + notes[-1].steps != step:
                raise ValueError(f"step {step}: '-' holds a note, but no note is sounding")
            last = notes.pop()
            notes.append(Note(last.step, last.steps + 1, last.name))
        elif token != ".":
            notes.append(Note(step, 1, token))
    return notes


def voice(score: str, instrument: Instrument,
          rng: random.Random) -> list[tuple[int, Samples]]:
    """Each note of a score played on ``instrument``, with its offset in samples."""
    return [(note.step * STEP_SAMPLES, render(steady(instrument, note.name, note.steps * STEP_S),
                                              rng))
            for note in parse_score(score)]


def drums(score: str, rng: random.Random) -> list[tuple[int, Samples]]:
    """Each hit of a drum score, with its offset in samples."""
    return [(note.step * STEP_SAMPLES, render(DRUM_KIT[note.name], rng))
            for note in parse_score(score)]


def music(rng: random.Random) -> Samples:
    """The loop: lead, bass and drums.

    Every note ends inside the loop, so its last sample and its first are both (nearly)
    silence and the loop joins without a click.
    """
    return mix(LOOP_STEPS * STEP_SAMPLES,
               [*voice(MELODY, LEAD, rng), *voice(BASS, BASS_VOICE, rng), *drums(DRUMS, rng)])


# --------------------------------------------------------------------------
# Writing WAV files
# --------------------------------------------------------------------------

def wav_bytes(samples: Sequence[float], rate_hz: int = SAMPLE_RATE_HZ) -> bytes:
    """A complete 16-bit mono WAV file holding ``samples`` (clipped to -1..1).

    >>> data = wav_bytes([0.0, 0.5, -1.0, 2.0])
    >>> len(data), data[:4], data[8:12]
    (52, b'RIFF', b'WAVE')
    """
    pcm = array("h", (max(-FULL_SCALE, min(FULL_SCALE, round(s * FULL_SCALE)))
                      for s in samples))
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:  # the wave module writes little-endian everywhere
        out.setnchannels(1)
        out.setsampwidth(SAMPLE_BYTES)
        out.setframerate(rate_hz)
        out.writeframes(pcm.tobytes())
    return buffer.getvalue()


Generator = Callable[[random.Random], Samples]

EFFECTS: dict[str, Generator] = {
    "jump": jump, "coin": coin, "stomp": stomp, "hurt": hurt, "exit": fanfare, "menu": menu,
    "tally": tally,
}
MUSIC_FILE = "music.wav"
ASSET_MODE = 0o644  # owner reads and writes, everyone reads


def synthesise_all() -> dict[str, bytes]:
    """Every sound file, by file name, as the bytes to write. Same bytes on every call."""
    files = {f"{name}.wav": wav_bytes(make(random.Random(EFFECTS_SEED)))
             for name, make in EFFECTS.items()}
    files[MUSIC_FILE] = wav_bytes(music(random.Random(MUSIC_SEED)))
    return files


def main() -> None:
    """Synthesise every sound and write it into ``assets/sounds``."""
    files = synthesise_all()
    SOUNDS.mkdir(parents=True, exist_ok=True)  # the one atomic write makes no folders
    for name, data in files.items():
        write_bytes_atomically(SOUNDS / name, data, ASSET_MODE)
    total_kb = sum(len(data) for data in files.values()) / 1024
    print(f"wrote {len(files)} sounds ({total_kb:.0f} KiB) to {SOUNDS}")


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
