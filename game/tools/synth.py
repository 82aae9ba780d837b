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
from itertools import accumulate, repeat

from game.app.files import write_bytes_atomically
from game.levels.closed_output import quiet_when_output_closes
from game.levels.shipped import ASSETS_DIR

ASSETS = ASSETS_DIR
SOUNDS = ASSETS / "sounds"

SAMPLE_RATE_HZ = 22050
SAMPLE_BYTES = 2  # 16-bit signed samples
FULL_SCALE = 32767  # the largest 16-bit sample: a sample of 1.0 is written as this
EIGHT_BIT_ZERO = 128  # an 8-bit WAV sample's silence
EIGHT_BIT_SCALE = 127  # a sample of 1.0 is written as 128 + 127
SIGNED_TO_UNSIGNED = bytes((b + EIGHT_BIT_ZERO) % 256 for b in range(256))  # a byte's -1 is 255

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


def samples_for(duration_s: float, rate_hz: int = SAMPLE_RATE_HZ) -> int:
    """How many samples last ``duration_s`` seconds.

    >>> samples_for(0.2), samples_for(1.0), samples_for(1.0, 11025)
    (4410, 22050, 11025)
    """
    return round(duration_s * rate_hz)


def envelope(instrument: Instrument, n: int, rate_hz: int = SAMPLE_RATE_HZ) -> list[float]:
    """The loudness of each of ``n`` samples: a linear attack, decay and release.

    It is 0 at the first sample and would be 0 again at sample ``n``, one past the end.

    >>> envelope(Instrument(Wave.SQUARE, volume=1.0, attack_s=2 / 22050, release_s=2 / 22050), 5)
    [0.0, 0.5, 1.0, 1.0, 0.5]
    """
    attack_n = max(1, samples_for(instrument.attack_s, rate_hz))
    release_n = max(1, samples_for(instrument.release_s, rate_hz))
    volume, fade = instrument.volume, instrument.sustain - 1.0
    return [volume * (i / attack_n if i < attack_n else 1.0)
            * ((n - i) / release_n if n - i < release_n else 1.0)
            * (1.0 + fade * i / n) for i in range(n)]


def render(tone: Tone, rng: random.Random, rate_hz: int = SAMPLE_RATE_HZ) -> Samples:
    """Play one tone into a fresh list of samples, ``rate_hz`` a second; ``rng`` feeds the
    noise wave."""
    instrument = tone.instrument
    n = samples_for(tone.duration_s, rate_hz)
    kind, duty = instrument.wave, instrument.duty
    start_hz, sweep_hz = tone.start_hz, tone.end_hz - tone.start_hz
    if sweep_hz == 0.0 and kind is not Wave.NOISE and n > 0:  # a steady note: same sums
        phases = accumulate(repeat(start_hz / rate_hz, n - 1), initial=0.0)
        volumes = envelope(instrument, n, rate_hz)
        if kind is Wave.SQUARE:
            return [(1.0 if phase % 1.0 < duty else -1.0) * volume
                    for phase, volume in zip(phases, volumes, strict=True)]
        return [triangle(phase) * volume for phase, volume in zip(phases, volumes, strict=True)]
    out: Samples = []
    phase = 0.0
    level = rng.uniform(-1.0, 1.0) if kind is Wave.NOISE else 0.0
    for i, loudness in enumerate(envelope(instrument, n, rate_hz)):
        if kind is Wave.SQUARE:
            value = 1.0 if phase % 1.0 < duty else -1.0  # square(phase, duty), inlined
        elif kind is Wave.TRIANGLE:
            p = (phase + 0.25) % 1.0  # triangle(phase), inlined
            value = 4.0 * p - 1.0 if p < 0.5 else 3.0 - 4.0 * p
        else:
            value = level
        out.append(value * loudness)
        next_phase = phase + (start_hz + sweep_hz * i / n) / rate_hz
        if kind is Wave.NOISE and math.floor(next_phase) != math.floor(phase):
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
        end = offset + len(samples)
        out[offset:end] = [a + b for a, b in zip(out[offset:end], samples, strict=True)]
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
TALLY_NOTES = (("G5", 0.05), ("A5", 0.05), ("B5", 0.05), ("D6", 0.05), ("G6", 0.35))
MENU = Tone(Instrument(Wave.SQUARE, volume=0.25, attack_s=0.001, release_s=0.01, sustain=0.3),
            start_hz=1800.0, end_hz=1200.0, duration_s=0.03)


def steady(instrument: Instrument, note: str, duration_s: float) -> Tone:
    """A note that holds its pitch, such as ``steady(CHIME, "C5", 0.09)``."""
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


def tally(rng: random.Random) -> Samples:
    """The level-end tally: a quick climb of chimes, one a line, landing on a ringing G."""
    *climb, (last, last_s) = TALLY_NOTES
    return in_sequence(rng, [*(steady(CHIME, note, s) for note, s in climb),
                             steady(CHIME_RING, last, last_s)])


def menu(rng: random.Random) -> Samples:
    """A click: a very short, falling, high blip."""
    return render(MENU, rng)


# --------------------------------------------------------------------------
# Jingles: short tunes read from tiny scores, for the moments between the playing
# --------------------------------------------------------------------------

# One token per step, "|" between bars: a note starts, "-" holds it, "." is silence.
JINGLE_STEP_S = 0.09  # one score token of a jingle


@dataclass(frozen=True)
class Note:
    step: int  # the score step it starts on
    steps: int  # how many steps it lasts
    name: str  # a note name, or a drum letter


def parse_score(score: str, steps: int) -> list[Note]:
    """Read a score: one token per step, ``-`` holds the last note, ``.`` rests.

    >>> parse_score("C4 - . | E4", 4)
    [Note(step=0, steps=2, name='C4'), Note(step=3, steps=1, name='E4')]
    >>> parse_score("C4 -", 3)
    Traceback (most recent call last):
        ...
    ValueError: the score has 2 steps, expected 3: every voice must fill the tune exactly
    """
    tokens = score.replace("|", " ").split()
    if len(tokens) != steps:
        raise ValueError(f"the score has {len(tokens)} steps, expected {steps}: "
                         "every voice must fill the tune exactly")
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


JINGLE_LEAD = Instrument(Wave.SQUARE, volume=0.25, release_s=0.03, sustain=0.7, duty=0.25)
JINGLE_BASS = Instrument(Wave.TRIANGLE, volume=0.35, attack_s=0.003, release_s=0.06,
                         sustain=0.6)
LANTERN_CHIME = Instrument(Wave.SQUARE, volume=0.22, release_s=0.04, sustain=0.3, duty=0.125)


@dataclass(frozen=True)
class Jingle:
    """A short tune: a lead and a bass score of the same number of steps."""

    lead: str
    bass: str
    lead_voice: Instrument = JINGLE_LEAD
    bass_voice: Instrument = JINGLE_BASS
    tail_steps: int = 4  # silence after the last step, so the last notes ring out


JINGLES = {
    # The lantern lights: a quick climb of bell-like chimes over a low fifth.
    "checkpoint": Jingle("E5 G#5 B5 E6 - - ", "E3 - - B3 - - ", LANTERN_CHIME, tail_steps=1),
    # A level cleared: a climb up the C chord, then a cadence home.
    "clear": Jingle("C5 E5 G5 C6 - - | A5 B5 C6 D6 - C6 | D6 - - E6 - - - -",
                    "C3 - - - - - | F3 - - G3 - - | C3 - - C4 - - - -"),
    # Game over: a slow chromatic fall to a low, minor end.
    "game-over": Jingle("G4 - - F#4 - - F4 - - E4 - - | D#4 - - - - - D4 - - - - . "
                        "| C4 - - - - - - - - - - .",
                        "C3 - - - - - B2 - - - - - | A#2 - - - - - A2 - - - - . "
                        "| C2 - - - - - - - - - - ."),
    # The campaign won: a climbing fanfare, a turn, and a long bright landing.
    "win": Jingle("C5 E5 G5 C6 - G5 | E5 G5 C6 E6 - - | F5 A5 C6 F6 - - "
                  "| G5 B5 D6 G6 - - | E6 - D6 - C6 - | C6 - - - - - - -",
                  "C3 - - C4 - - | C3 - - C4 - - | F2 - - F3 - - | G2 - - G3 - - "
                  "| G2 - - G2 - - | C3 - - - - - - -"),
}


def jingle(tune: Jingle, rng: random.Random) -> Samples:
    """A jingle's lead over its bass, with a tail of silence for the last notes' release."""
    steps = len(tune.lead.replace("|", " ").split())
    step_n = samples_for(JINGLE_STEP_S)
    parts = [(note.step * step_n, render(steady(voice_of, note.name, note.steps * JINGLE_STEP_S),
                                         rng))
             for score, voice_of in ((tune.lead, tune.lead_voice), (tune.bass, tune.bass_voice))
             for note in parse_score(score, steps)]
    return mix((steps + tune.tail_steps) * step_n, parts)


# --------------------------------------------------------------------------
# The music: a loop for the title and for each place, composed from a few seeded choices
# --------------------------------------------------------------------------
#
# A song is a chord progression in two 4-bar phrases, A and B, played in a form such as
# AABA. The lead's melody is made once per phrase by a seeded random walk (chord tones on
# the strong eighths, steps along the scale between them), so A sounds the same each time
# it comes back. Under it, a bass line and an arpeggio follow the chords, and drums keep
# time. The music is written at half the effects' sample rate and 8 bits a sample (a
# quarter of the bytes: a chip's voice loses nothing by it), and every note ends inside
# the loop, so it joins up without a click.

MUSIC_RATE_HZ = SAMPLE_RATE_HZ // 2  # 11025
MUSIC_SAMPLE_BYTES = 1  # 8-bit unsigned samples, as WAV stores them
MUSIC_MIN_S = 30.0  # every loop lasts at least this long
STEPS_PER_BAR = 8  # eighth notes
BARS_PER_PHRASE = 4
MAJOR = (0, 2, 4, 5, 7, 9, 11)  # semitones above the key's root
MINOR = (0, 2, 3, 5, 7, 8, 10)
NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")
RHYTHMS = (  # where a melody's notes start in a bar: x starts, - holds, . rests
    "x-x-x-x-", "x-xxx-x-", "x---x-x-", "x-x-x---", "xx-x-x-x", "x--x--x-", "x-x-xx-.",
)
LAST_BAR = "x-------"  # a phrase ends on one long note


@dataclass(frozen=True)
class Song:
    """What makes one loop its own: its pace, its key, its chords, its voices."""

    seed: int
    tempo_bpm: int
    key: str  # the scale's root, such as "C" or "A"
    minor: bool
    phrase_a: tuple[str, ...]  # one chord a bar, such as ("C", "Am", "F", "G")
    phrase_b: tuple[str, ...]
    form: str  # the phrases in order, such as "AABA"
    drums: str  # one bar: k kick, h hi-hat, s snare, . nothing
    bass: str  # "octaves", "roots" or "walk"
    lead_octave: int  # the melody's home octave
    lead: Instrument
    arp: Instrument | None = None  # a quiet broken chord under the lead, or none


def chord_notes(chord: str) -> tuple[int, ...]:
    """The semitones (0 is C) of a chord named like ``"F#"`` or ``"Am"``.

    >>> chord_notes("C"), chord_notes("Am")
    ((0, 4, 7), (9, 12, 16))
    """
    minor = chord.endswith("m")
    root = NOTE_NAMES.index(chord[:-1] if minor else chord)
    return (root, root + (3 if minor else 4), root + 7)


def note_name(midi: int) -> str:
    """The name of a MIDI note number: 60 is C4.

    >>> note_name(60), note_name(69), note_name(45)
    ('C4', 'A4', 'A2')
    """
    return f"{NOTE_NAMES[midi % 12]}{midi // 12 - 1}"


def song_bars(song: Song) -> list[str]:
    """The chord of every bar of the loop, in order."""
    phrases = {"A": song.phrase_a, "B": song.phrase_b}
    return [chord for part in song.form for chord in phrases[part]]


def step_samples(song: Song) -> int:
    """How many samples an eighth note of ``song`` lasts."""
    return round(60.0 / song.tempo_bpm / 2 * MUSIC_RATE_HZ)


def compose_phrase(song: Song, chords: Sequence[str], rng: random.Random) -> list[Note]:
    """A melody for one phrase: chord tones on the strong eighths, the scale between."""
    scale = MINOR if song.minor else MAJOR
    key = NOTE_NAMES.index(song.key)
    home = 12 * (song.lead_octave + 1) + key
    pitches = [home + 12 * octave + degree for octave in (-1, 0, 1) for degree in scale]
    at = pitches.index(home)
    notes: list[Note] = []
    for bar, chord in enumerate(chords):
        rhythm = LAST_BAR if bar == len(chords) - 1 else rng.choice(RHYTHMS)
        tones = {n % 12 for n in chord_notes(chord)}
        for step, mark in enumerate(rhythm):
            if mark != "x":
                continue
            if step % 4 == 0:  # a strong eighth: the nearest chord tone to a small leap
                target = at + rng.choice((-2, -1, 0, 1, 2))
                choices = [i for i in range(len(pitches)) if pitches[i] % 12 in tones]
                at = min(choices, key=lambda i: (abs(i - target), i))
            else:  # a passing note: a step or two along the scale
                at = min(len(pitches) - 1, max(0, at + rng.choice((-2, -1, 1, 2))))
            length = 1
            while step + length < STEPS_PER_BAR and rhythm[step + length] == "-":
                length += 1
            notes.append(Note(bar * STEPS_PER_BAR + step, length, note_name(pitches[at])))
    return notes


def bass_line(song: Song, bars: Sequence[str]) -> list[Note]:
    """The bass under every bar: the chord's root in the style the song names."""
    notes: list[Note] = []
    for bar, chord in enumerate(bars):
        root = 12 * 3 + chord_notes(chord)[0] % 12  # octave 2
        fifth = root + 7
        pattern = {"octaves": (root, root + 12) * 4, "roots": (root,) * 4,
                   "walk": (root, fifth, root + 12, fifth)}[song.bass]
        length = STEPS_PER_BAR // len(pattern)
        notes.extend(Note(bar * STEPS_PER_BAR + i * length, length, note_name(pitch))
                     for i, pitch in enumerate(pattern))
    return notes


def arpeggio(bars: Sequence[str], octave: int) -> list[Note]:
    """A broken chord, one tone an eighth, rising and falling through each bar's chord."""
    order = (0, 1, 2, 1, 0, 1, 2, 1)
    notes: list[Note] = []
    for bar, chord in enumerate(bars):
        tones = chord_notes(chord)
        notes.extend(Note(bar * STEPS_PER_BAR + step,
                          1, note_name(12 * (octave + 1) + tones[index]))
                     for step, index in enumerate(order))
    return notes


def place_notes(notes: Iterable[Note], instrument: Instrument, step_n: int,
                cache: dict[tuple[str, int], Samples]) -> list[tuple[int, Samples]]:
    """Each note rendered once per pitch and length (a steady tone needs no noise), with
    its offset in samples."""
    parts: list[tuple[int, Samples]] = []
    no_noise = random.Random(0)  # unused: square and triangle waves draw no random numbers
    for note in notes:
        key = (note.name, note.steps)
        if key not in cache:
            cache[key] = render(steady(instrument, note.name, note.steps * step_n
                                       / MUSIC_RATE_HZ), no_noise, MUSIC_RATE_HZ)
        parts.append((note.step * step_n, cache[key]))
    return parts


MUSIC_KIT = {
    "k": Tone(Instrument(Wave.TRIANGLE, volume=0.3, attack_s=0.001, sustain=0.2),
              start_hz=150.0, end_hz=50.0, duration_s=0.1),
    "h": Tone(Instrument(Wave.NOISE, volume=0.06, attack_s=0.001, release_s=0.03, sustain=0.0),
              start_hz=5000.0, end_hz=5000.0, duration_s=0.04),
    "s": Tone(Instrument(Wave.NOISE, volume=0.11, attack_s=0.001, release_s=0.05, sustain=0.2),
              start_hz=4000.0, end_hz=2500.0, duration_s=0.12),
}
MUSIC_BASS = Instrument(Wave.TRIANGLE, volume=0.3, attack_s=0.003, sustain=0.7)


def lay(length: int, parts: Iterable[tuple[int, Samples]]) -> Samples:
    """One voice's ``length`` samples: each ``(offset, samples)`` part in its place and
    silence between. A voice plays one note at a time, so its parts never overlap, and
    laying them end to end is much quicker than :func:`mix`.

    >>> lay(5, [(1, [0.5, 0.5]), (3, [0.25])])
    [0.0, 0.5, 0.5, 0.25, 0.0]
    """
    out: Samples = []
    for offset, samples in sorted(parts, key=lambda part: part[0]):
        if offset < len(out) or offset + len(samples) > length:
            raise ValueError(f"a part at sample {offset} overlaps the one before it or runs "
                             f"past the end ({length} samples): one voice plays one note "
                             "at a time")
        out.extend(repeat(0.0, offset - len(out)))
        out.extend(samples)
    out.extend(repeat(0.0, length - len(out)))
    return out


def song(tune: Song) -> Samples:
    """The whole loop of ``tune``: lead, arpeggio, bass and drums, at :data:`MUSIC_RATE_HZ`."""
    rng = random.Random(tune.seed)
    bars = song_bars(tune)
    step_n = step_samples(tune)
    length = len(bars) * STEPS_PER_BAR * step_n
    phrases = {part: compose_phrase(tune, chords, rng)
               for part, chords in (("A", tune.phrase_a), ("B", tune.phrase_b))}
    bar_steps = BARS_PER_PHRASE * STEPS_PER_BAR
    melody = [Note(number * bar_steps + note.step, note.steps, note.name)
              for number, part in enumerate(tune.form) for note in phrases[part]]
    voices = [lay(length, place_notes(melody, tune.lead, step_n, {})),
              lay(length, place_notes(bass_line(tune, bars), MUSIC_BASS, step_n, {}))]
    if tune.arp is not None:
        voices.append(lay(length, place_notes(arpeggio(bars, tune.lead_octave - 1), tune.arp,
                                              step_n, {})))
    hits = {letter: render(tone, rng, MUSIC_RATE_HZ) for letter, tone in MUSIC_KIT.items()}
    pattern = tune.drums.split()
    voices.append(lay(length, [((bar * STEPS_PER_BAR + step) * step_n, hits[letter])
                               for bar in range(len(bars)) for step, letter in enumerate(pattern)
                               if letter in hits]))
    return [sum(values) for values in zip(*voices, strict=True)]


LEAD_BRIGHT = Instrument(Wave.SQUARE, volume=0.18, release_s=0.03, sustain=0.55, duty=0.25)
LEAD_HOLLOW = Instrument(Wave.SQUARE, volume=0.18, release_s=0.04, sustain=0.7, duty=0.5)
LEAD_THIN = Instrument(Wave.SQUARE, volume=0.16, release_s=0.05, sustain=0.5, duty=0.125)
LEAD_SOFT = Instrument(Wave.TRIANGLE, volume=0.32, release_s=0.05, sustain=0.6)
ARP = Instrument(Wave.SQUARE, volume=0.06, release_s=0.01, sustain=0.3, duty=0.125)

SONGS = {  # music-NAME.wav: the title screen's, then one for each place
    "title": Song(2024, 125, "C", False, ("C", "Am", "F", "G"), ("F", "G", "Em", "Am"),
                  "AABA", "k h s h k h s h", "octaves", 5, LEAD_BRIGHT, ARP),
    "meadow": Song(11, 126, "G", False, ("G", "Em", "C", "D"), ("C", "D", "G", "Em"),
                   "AABA", "k h s h k h s h", "octaves", 5, LEAD_BRIGHT),
    "cliffs": Song(23, 120, "D", False, ("D", "G", "A", "D"), ("Bm", "G", "Em", "A"),
                   "AABA", "k . s h k k s h", "walk", 5, LEAD_HOLLOW, ARP),
    "forest": Song(37, 124, "A", True, ("Am", "F", "C", "G"), ("Dm", "Am", "E", "Am"),
                   "AABA", "k . h . s . h .", "roots", 4, LEAD_SOFT, ARP),
    "caves": Song(41, 95, "E", True, ("Em", "C", "Em", "B"), ("Am", "Em", "C", "B"),
                  "ABA", "k . . h . . s .", "roots", 4, LEAD_THIN),
    "dusk": Song(53, 127, "F", False, ("F", "Dm", "A#", "C"), ("Gm", "C", "F", "Dm"),
                 "AABA", "k . h h s . h .", "walk", 5, LEAD_SOFT, ARP),
    "summit": Song(67, 128, "E", False, ("E", "C#m", "A", "B"), ("A", "B", "G#m", "C#m"),
                   "AABB", "k h s h k k s h", "octaves", 5, LEAD_BRIGHT, ARP),
}


# --------------------------------------------------------------------------
# Writing WAV files
# --------------------------------------------------------------------------

def wav_bytes(samples: Sequence[float], rate_hz: int = SAMPLE_RATE_HZ,
              sample_bytes: int = SAMPLE_BYTES) -> bytes:
    """A complete mono WAV file holding ``samples`` (clipped to -1..1): 16-bit signed
    samples, or with ``sample_bytes=1`` 8-bit ones, which WAV stores unsigned around 128.

    >>> data = wav_bytes([0.0, 0.5, -1.0, 2.0])
    >>> len(data), data[:4], data[8:12]
    (52, b'RIFF', b'WAVE')
    >>> wav_bytes([0.0, 0.5, -1.0, 2.0], 11025, 1)[44:]
    b'\\x80\\xc0\\x01\\xff'
    """
    if sample_bytes == 1:
        top, bottom = EIGHT_BIT_SCALE, -EIGHT_BIT_SCALE
        signed = array("b", (q if bottom <= q <= top else (top if q > 0 else bottom)
                             for q in [round(s * top) for s in samples]))
        pcm = array("B", signed.tobytes().translate(SIGNED_TO_UNSIGNED))
    else:
        pcm = array("h", (max(-FULL_SCALE, min(FULL_SCALE, round(s * FULL_SCALE)))
                          for s in samples))
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as out:  # the wave module writes little-endian everywhere
        out.setnchannels(1)
        out.setsampwidth(sample_bytes)
        out.setframerate(rate_hz)
        out.writeframes(pcm.tobytes())
    return buffer.getvalue()


Generator = Callable[[random.Random], Samples]

EFFECTS: dict[str, Generator] = {
    "jump": jump, "coin": coin, "stomp": stomp, "hurt": hurt, "menu": menu, "tally": tally,
}
ASSET_MODE = 0o644  # owner reads and writes, everyone reads


def music_file(name: str) -> str:
    """The file a song is written to: ``music-NAME.wav``."""
    return f"music-{name}.wav"


def synthesise_all() -> dict[str, bytes]:
    """Every sound file, by file name, as the bytes to write. Same bytes on every call."""
    files = {f"{name}.wav": wav_bytes(make(random.Random(EFFECTS_SEED)))
             for name, make in EFFECTS.items()}
    files |= {f"{name}.wav": wav_bytes(jingle(tune, random.Random(EFFECTS_SEED)))
              for name, tune in JINGLES.items()}
    files |= {music_file(name): wav_bytes(song(tune), MUSIC_RATE_HZ, MUSIC_SAMPLE_BYTES)
              for name, tune in SONGS.items()}
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
