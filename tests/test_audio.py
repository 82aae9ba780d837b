"""The synthesised sounds are well-formed and reproducible; Audio plays them or stays silent."""

from __future__ import annotations

import io
import itertools
import operator
import os
import random
import sys
import time
import wave
from array import array
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pygame
import pytest

from game.app.audio import (
    EFFECT_NAMES,
    MUSIC_TRACKS,
    SOUND_FOR_EVENT,
    SOUNDS,
    TITLE_TRACK,
    Audio,
    music_file,
)
from game.app.places import PLACES
from game.sim.world import EventKind
from game.tools import synth

QUIET = 0.002 * synth.FULL_SCALE  # a sample this small is inaudible: about -54 dBFS
JINGLES = ("checkpoint", "clear", "game-over", "win")
EFFECTS = tuple(name for name in EFFECT_NAMES if name not in JINGLES)
MUSIC_FILES = tuple(music_file(track) for track in MUSIC_TRACKS)


@pytest.fixture(scope="module")
def sounds() -> dict[str, bytes]:
    return synth.synthesise_all()


@pytest.fixture(autouse=True)
def no_mixer() -> Iterator[None]:
    """Each test starts and ends with the mixer closed."""
    pygame.mixer.quit()
    yield
    pygame.mixer.quit()


@dataclass(frozen=True)
class Wav:
    channels: int
    sample_bytes: int
    rate_hz: int
    compression: str
    frames: int


# An 8-bit sample's byte (unsigned, 128 the silence) made the high byte of a 16-bit one.
TO_SIGNED = bytes(byte ^ 0x80 for byte in range(256))


def decode(data: bytes) -> tuple[Wav, array[int]]:
    """The file's format and its samples, 16-bit signed (an 8-bit file's scaled up: sample
    ``byte`` becomes ``(byte - 128) * 256``, built byte by byte in C, not one by one)."""
    with wave.open(io.BytesIO(data)) as reader:
        params = Wav(reader.getnchannels(), reader.getsampwidth(), reader.getframerate(),
                     reader.getcomptype(), reader.getnframes())
        frames = reader.readframes(params.frames)
    if params.sample_bytes == 1:
        wide = bytearray(2 * len(frames))  # the low bytes stay 0
        wide[1 if sys.byteorder == "little" else 0::2] = frames.translate(TO_SIGNED)
        return params, array("h", wide)
    return params, array("h", frames)


def zero_crossings(samples: array[int] | list[int]) -> int:
    return sum(1 for a, b in itertools.pairwise(samples) if (a < 0) != (b < 0))


# --- Synthesis ------------------------------------------------------------------------------

def test_shipped_sounds_match_the_generator(sounds: dict[str, bytes]) -> None:
    """The files were made by another run of the generator: that this run gives the same
    bytes shows both that they are up to date and that synthesis is reproducible."""
    shipped = {path.name: path.read_bytes() for path in SOUNDS.glob("*.wav")}
    stale = sorted(name for name in sounds if shipped.get(name) != sounds[name])
    assert not stale, f"{stale} are out of date: run python -m game.tools.synth"


def test_every_sound_the_game_plays_is_made(sounds: dict[str, bytes]) -> None:
    assert set(sounds) == {f"{name}.wav" for name in EFFECT_NAMES} | set(MUSIC_FILES)


def test_the_title_and_every_place_have_music_of_their_own(sounds: dict[str, bytes]) -> None:
    assert (TITLE_TRACK, *PLACES) == MUSIC_TRACKS
    assert tuple(synth.SONGS) == MUSIC_TRACKS
    assert len({sounds[name] for name in MUSIC_FILES}) == len(MUSIC_FILES)


@pytest.mark.parametrize("name", [f"{n}.wav" for n in EFFECT_NAMES])
def test_every_effect_is_16_bit_mono_at_22050_hz(sounds: dict[str, bytes], name: str) -> None:
    params, samples = decode(sounds[name])
    assert (params.channels, params.sample_bytes, params.rate_hz) == (1, 2, 22050)
    assert params.compression == "NONE"
    assert len(samples) == params.frames
    assert len(sounds[name]) == 44 + 2 * params.frames  # a plain 44-byte RIFF header


@pytest.mark.parametrize("name", MUSIC_FILES)
def test_music_is_8_bit_mono_at_11025_hz(sounds: dict[str, bytes], name: str) -> None:
    params, _ = decode(sounds[name])
    assert (params.channels, params.sample_bytes, params.rate_hz) == (1, 1, 11025)
    assert params.compression == "NONE"
    assert len(sounds[name]) == 44 + params.frames  # a plain 44-byte RIFF header


@pytest.mark.parametrize("name", EFFECTS)
def test_effects_are_short(sounds: dict[str, bytes], name: str) -> None:
    params, _ = decode(sounds[f"{name}.wav"])
    assert 0.02 <= params.frames / params.rate_hz <= 0.8


@pytest.mark.parametrize("name", JINGLES)
def test_jingles_are_made_and_last_at_most_4_s(sounds: dict[str, bytes], name: str) -> None:
    params, _ = decode(sounds[f"{name}.wav"])
    assert 0.3 <= params.frames / params.rate_hz <= 4.0


@pytest.mark.parametrize("track", MUSIC_TRACKS)
def test_each_loop_lasts_a_whole_number_of_bars_of_at_least_30_s(
        sounds: dict[str, bytes], track: str) -> None:
    params, _ = decode(sounds[music_file(track)])
    tune = synth.SONGS[track]
    bars = len(synth.song_bars(tune))
    assert params.frames == bars * synth.STEPS_PER_BAR * synth.step_samples(tune)
    assert 30.0 <= params.frames / params.rate_hz <= 40.0


@pytest.mark.parametrize("name", [*(f"{n}.wav" for n in EFFECT_NAMES), *MUSIC_FILES])
def test_no_sound_clips_or_clicks_at_its_ends(sounds: dict[str, bytes], name: str) -> None:
    _, samples = decode(sounds[name])
    assert max(abs(s) for s in samples) < synth.FULL_SCALE
    assert samples[0] == 0
    assert abs(samples[-1]) <= QUIET


@pytest.mark.parametrize("name", MUSIC_FILES)
def test_music_loop_joins_without_a_jump(sounds: dict[str, bytes], name: str) -> None:
    _, samples = decode(sounds[name])
    wrap = abs(samples[0] - samples[-1])
    assert wrap <= QUIET
    steps = sorted(map(abs, map(operator.sub, samples[1:], samples[:-1])))  # b - a, in C
    assert wrap <= steps[len(steps) // 2]  # no bigger than a typical step inside the loop


def test_all_sounds_fit_in_a_small_download(sounds: dict[str, bytes]) -> None:
    """Seven loops of 30 s or more at 11 kB a second, and the effects and jingles."""
    assert sum(len(data) for data in sounds.values()) < 3_000_000


def test_jump_rises_and_hurt_falls(sounds: dict[str, bytes]) -> None:
    _, jump = decode(sounds["jump.wav"])
    _, hurt = decode(sounds["hurt.wav"])
    half = len(jump) // 2
    assert zero_crossings(jump[half:]) > 1.5 * zero_crossings(jump[:half])
    half = len(hurt) // 2
    assert zero_crossings(hurt[:half]) > 1.5 * zero_crossings(hurt[half:])


def test_a_sweep_keeps_its_wave_continuous() -> None:
    tone = synth.Tone(synth.Instrument(synth.Wave.TRIANGLE, volume=1.0, attack_s=0.0,
                                       release_s=0.0), 100.0, 2000.0, 0.1)
    samples = synth.render(tone, random.Random(0))
    biggest_step = max(abs(b - a) for a, b in itertools.pairwise(samples))
    assert biggest_step <= 4 * 2000.0 / synth.SAMPLE_RATE_HZ + 1e-9  # a triangle's slope


def test_a_score_that_does_not_fill_the_loop_is_refused() -> None:
    with pytest.raises(ValueError, match="expected 64"):
        synth.parse_score("C4 - - -", 64)


def test_one_voice_plays_one_note_at_a_time() -> None:
    with pytest.raises(ValueError, match="one voice plays one note at a time"):
        synth.lay(10, [(0, [0.5] * 4), (3, [0.5])])


def test_a_steady_note_is_the_sweep_of_one_pitch_to_the_last_bit() -> None:
    """The quick path for a steady note adds the same numbers in the same order."""
    for wave_kind in (synth.Wave.SQUARE, synth.Wave.TRIANGLE):
        instrument = synth.Instrument(wave_kind, duty=0.25)
        steady = synth.Tone(instrument, 440.0, 440.0, 0.05)
        almost = synth.Tone(instrument, 440.0, 440.0 + 1e-12, 0.05)
        a = synth.render(steady, random.Random(0))
        b = synth.render(almost, random.Random(0))
        assert len(a) == len(b) and max(abs(x - y) for x, y in zip(a, b, strict=True)) < 1e-6


def test_main_writes_every_sound_readable_by_everyone(tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch,
                                                      sounds: dict[str, bytes]) -> None:
    monkeypatch.setattr(synth, "SOUNDS", tmp_path / "sounds")
    monkeypatch.setattr(synth, "synthesise_all", lambda: sounds)
    (tmp_path / "sounds").mkdir()  # the sounds' folder is the project's: the tool makes none
    synth.main()
    written = {path.name: path for path in (tmp_path / "sounds").iterdir()}
    assert set(written) == set(sounds)
    assert all(path.read_bytes() == sounds[name] for name, path in written.items())
    if os.name == "posix":
        assert all(path.stat().st_mode & 0o777 == synth.ASSET_MODE for path in written.values())


# --- Audio ----------------------------------------------------------------------------------

def test_audio_loads_and_plays_every_sound_on_the_dummy_driver() -> None:
    audio = Audio()
    try:
        assert not audio.silent and audio.status == "Sound is on."
        for name in EFFECT_NAMES:
            audio.play(name)
        for kind in EventKind:
            audio.play(kind)
        audio.start_music()
        assert pygame.mixer.music.get_busy()
        audio.start_music()  # already playing: carries on rather than restarting
        assert pygame.mixer.music.get_busy()
    finally:
        audio.close()
    assert not pygame.mixer.get_init()


def test_paused_music_resumes_rather_than_restarting() -> None:
    audio = Audio()
    try:
        audio.start_music()
        waited_s = 0.0
        while pygame.mixer.music.get_pos() <= 0 and waited_s < 5.0:
            time.sleep(0.05)  # the dummy driver plays in real time: let some of it play
            waited_s += 0.05
        audio.pause_music()
        assert not pygame.mixer.music.get_busy()
        played_ms = pygame.mixer.music.get_pos()
        assert played_ms > 0
        audio.start_music()
        assert pygame.mixer.music.get_busy()
        assert pygame.mixer.music.get_pos() >= played_ms  # a restart would start from 0
        audio.stop_music()
        assert not pygame.mixer.music.get_busy()
    finally:
        audio.close()


def test_audio_is_silent_without_a_word_when_the_mixer_cannot_open(
        monkeypatch: pytest.MonkeyPatch, capfd: pytest.CaptureFixture[str]) -> None:
    def no_device(*args: object, **kwargs: object) -> None:
        os.write(2, b"ALSA lib pcm.c:2666:(snd_pcm_open_noupdate) Unknown PCM default\n")
        raise pygame.error("ALSA: Couldn't open audio device")

    monkeypatch.setattr(pygame.mixer, "init", no_device)
    audio = Audio()
    audio.play("coin")
    audio.play(EventKind.JUMP)
    audio.start_music()
    audio.pause_music()
    audio.set_volume(0.5, 0.5)
    audio.stop_music()
    audio.close()
    assert audio.silent
    assert "no audio device" in audio.status
    assert capfd.readouterr() == ("", "")


def test_audio_turned_off_never_opens_the_mixer(monkeypatch: pytest.MonkeyPatch) -> None:
    def must_not_open(*args: object, **kwargs: object) -> None:
        raise AssertionError("the mixer was opened")

    monkeypatch.setattr(pygame.mixer, "init", must_not_open)
    audio = Audio(enabled=False)
    audio.play("clear")
    audio.start_music("caves")
    assert audio.silent and audio.track is None


def test_a_missing_file_silences_only_that_sound(tmp_path: Path,
                                                 sounds: dict[str, bytes]) -> None:
    (tmp_path / "coin.wav").write_bytes(sounds["coin.wav"])
    (tmp_path / "jump.wav").write_bytes(b"not a wav file")
    audio = Audio(tmp_path)
    try:
        assert not audio.silent
        assert "jump.wav" in audio.status and "music-title.wav" in audio.status
        assert "coin.wav" not in audio.status
        assert "python -m game.tools.synth" in audio.status
        audio.play("jump")
        audio.play("coin")
        audio.start_music()
        assert not pygame.mixer.music.get_busy()
    finally:
        audio.close()


def test_an_unknown_sound_name_is_a_mistake_even_when_silent() -> None:
    with pytest.raises(ValueError, match="no sound is called 'jmup'"):
        Audio(enabled=False).play("jmup")


def test_set_volume_clamps_to_0_to_1_and_reaches_the_mixer() -> None:
    audio = Audio()
    try:
        audio.set_volume(effects=2.0, music=-1.0)
        assert audio.volumes == (1.0, 0.0)
        audio.set_volume(effects=0.25, music=0.5)
        assert audio.volumes == (0.25, 0.5)
        assert pygame.mixer.music.get_volume() == pytest.approx(0.5, abs=0.01)
        assert all(sound.get_volume() == pytest.approx(0.25, abs=0.01)
                   for sound in audio._effects.values())
    finally:
        audio.close()


def test_world_events_play_the_sound_of_the_same_name_and_the_exit_the_clear() -> None:
    assert set(SOUND_FOR_EVENT.values()) <= set(EFFECT_NAMES)
    assert SOUND_FOR_EVENT[EventKind.EXIT] == "clear"
    assert all(SOUND_FOR_EVENT[kind] == kind.value for kind in SOUND_FOR_EVENT
               if kind is not EventKind.EXIT)


def test_touching_a_checkpoint_makes_a_sound() -> None:
    assert SOUND_FOR_EVENT[EventKind.CHECKPOINT] == "checkpoint"


def test_asking_for_another_track_swaps_the_music_and_the_same_one_carries_on() -> None:
    audio = Audio()
    try:
        audio.start_music(TITLE_TRACK)
        assert audio.track == TITLE_TRACK and pygame.mixer.music.get_busy()
        audio.start_music("caves")
        assert audio.track == "caves" and pygame.mixer.music.get_busy()
        audio.pause_music()
        audio.start_music("caves")  # paused: resumes the same track
        assert audio.track == "caves" and pygame.mixer.music.get_busy()
        audio.stop_music()
        assert audio.track is None
        with pytest.raises(ValueError, match="no music is called 'cave'"):
            audio.start_music("cave")
    finally:
        audio.close()
