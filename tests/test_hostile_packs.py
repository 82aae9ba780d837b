"""Well-formed but hostile level packs: each is rebuilt from its description and must end in
one sentence, its exit status, no traceback, and nothing opened outside the pack's folder.

The packs: a project whose ``assets`` or ``levels`` is a link out, a map that is itself a
link, ``--watch`` led to files by elements the loader never reads, a GIF whose frame is
larger than its screen after a stray byte. Where ``strace`` is installed, the commands are
run under it and every file they open is compared with the pack's folder.
"""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import pygame
import pytest

from game.app.watch import FileWatcher, level_files
from game.levels import check_level, load_level
from game.levels.images import header_size
from tests.test_loader import OBJECTS, TILESET, write_map

ROOT = Path(__file__).resolve().parent.parent
ENV = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy",
       "PYTHONDONTWRITEBYTECODE": "1", "PYTHONWARNINGS": "ignore"}
MAX_MESSAGE_CHARS = 1_000
STRACE = shutil.which("strace")
# The 47-byte GIF: a 16x16 screen, a stray byte, then a 65535x65535 frame.
HOSTILE_GIF = (b"GIF89a" + struct.pack("<HH", 16, 16) + b"\x80\0\0" + bytes(6)
               + b"!\xf9\x04" + bytes(4) + b"\0"  # a graphic control extension
               + b"\x00" + b"," + struct.pack("<HHHH", 0, 0, 65535, 65535) + b"\0"
               + b"\x02\x05\x44\x01\x00\x00\x00\0;")


def one_sentence(text: str) -> str:
    """The single line of ``text``; fail if it is empty, several lines or a traceback."""
    assert "Traceback" not in text, text
    lines = text.strip().splitlines()
    assert len(lines) == 1, text[:MAX_MESSAGE_CHARS]
    assert 0 < len(lines[0]) <= MAX_MESSAGE_CHARS and " — " in lines[0]
    return lines[0]


def run(args: list[str], cwd: Path, traced: Path | None = None
        ) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` in ``cwd``; with ``traced``, under strace writing to that file."""
    command = [sys.executable, *args]
    if traced is not None:
        assert STRACE is not None
        command = [STRACE, "-f", "-qq", "-e", "trace=open,openat", "-o", str(traced), *command]
    return subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True,
                          timeout=120, check=False)


def opened_outside(trace: Path, pack: Path, secret: Path) -> list[str]:
    """Files under ``secret`` that the traced command opened (``pack`` is where it may)."""
    named = re.findall(r'open(?:at)?\([^"]*"([^"]+)"', trace.read_text(errors="replace"))
    return [name for name in named if name.startswith(str(secret))
            and not name.startswith(str(pack))]


def tiny_png(path: Path, size: tuple[int, int] = (64, 16)) -> None:
    pygame.image.save(pygame.Surface(size), str(path))


def secret_tileset(folder: Path) -> Path:
    """A valid tileset and image somewhere a pack should never reach."""
    folder.mkdir()
    tiny_png(folder / "secret.png")
    (folder / "secret.tsx").write_text(
        TILESET.format(image='<image source="secret.png" width="64" height="16"/>')
        .replace('firstgid="1" ', ""), encoding="utf-8")
    return folder / "secret.tsx"


# -- one sandbox -----------------------------------------------------------------------------

def linked_project(tmp_path: Path, link: str) -> tuple[Path, Path, Path]:
    """A pack whose ``link`` folder (assets or levels) is a symbolic link to ``/``, and a map
    in it naming a tileset elsewhere on the machine through that link."""
    secret = secret_tileset(tmp_path / "secret")
    pack = tmp_path / "pack"
    pack.mkdir()
    for name in ("levels", "assets"):
        if name == link:
            os.symlink("/", pack / name)
        else:
            (pack / name).mkdir()
    folder = pack / "levels" if link == "assets" else pack
    reference = f"../{link}{secret}"
    tileset = f'<tileset firstgid="1" source="{reference}"/>'
    return pack, write_map(folder, tileset=tileset), secret


def test_a_project_whose_assets_folder_links_to_the_root_is_not_a_project(
        tmp_path: Path) -> None:
    pack, level, secret = linked_project(tmp_path, "assets")
    [error] = check_level(level).errors
    assert "leads outside the level's folder" in str(error)
    done = run(["-m", "game.levels", "check", str(level), "--no-solve"], pack,
               tmp_path / "trace" if STRACE else None)
    assert done.returncode == 1 and "Traceback" not in done.stderr + done.stdout
    assert "leads outside" in done.stdout and "all playable" not in done.stdout
    if STRACE:
        assert opened_outside(tmp_path / "trace", pack, secret.parent) == []


def test_a_project_whose_levels_folder_is_a_link_trusts_only_the_map_folder(
        tmp_path: Path) -> None:
    _pack, level, _secret = linked_project(tmp_path, "levels")
    [error] = check_level(level).errors
    assert "leads outside the level's folder" in str(error)


def test_a_map_that_is_a_link_to_a_map_elsewhere_is_refused_unread(tmp_path: Path) -> None:
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    real_map = write_map(elsewhere)
    pack = tmp_path / "pack"
    pack.mkdir()
    os.symlink(real_map, pack / "level.tmx")
    with pytest.raises(Exception) as caught:
        load_level(pack / "level.tmx")
    assert "the map is a link that leads outside its folder" in str(caught.value)
    done = run(["-m", "game.levels", "check", str(pack), "--no-solve"], tmp_path,
               tmp_path / "trace" if STRACE else None)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "link that leads outside" in done.stdout
    if STRACE:
        assert opened_outside(tmp_path / "trace", pack, elsewhere) == []
    game = run(["-m", "game", "--headless", "--ticks", "5", "--level",
                str(pack / "level.tmx")], tmp_path)
    assert game.returncode == 1
    assert "link that leads outside" in one_sentence(game.stderr)


def test_a_link_to_a_map_inside_the_same_folder_is_still_read(tmp_path: Path) -> None:
    level = write_map(tmp_path)
    os.symlink(level.name, tmp_path / "alias.tmx")
    assert load_level(tmp_path / "alias.tmx").spawn == load_level(level).spawn


# -- --watch watches what the loader read -----------------------------------------------------

def test_watch_never_follows_what_the_loader_does_not_read(tmp_path: Path) -> None:
    """A <tileset> hidden in a group, an absolute template on a layer and an image on a
    property: the loader reads none of them, so the watcher does not even stat them, and a
    FIFO among them cannot freeze it."""
    secret = secret_tileset(tmp_path / "secret")
    pack = tmp_path / "pack"
    pack.mkdir()
    os.mkfifo(pack / "trap.tsx")
    body = (f'<group name="g"><tileset firstgid="50" source="{secret}"/>'
            f'<tileset firstgid="60" source="trap.tsx"/></group>'
            f'<layer name="ground" width="4" height="3" template="{secret}">'
            '<data encoding="csv">0,0,0,0,\n0,0,0,0,\n1,1,1,1</data></layer>')
    level = write_map(pack, body)
    watched = level_files(level)
    assert watched == [level]
    assert not any(str(path).startswith(str(secret.parent)) for path in watched)
    assert not FileWatcher(level).poll(10.0)


def test_watch_lists_the_tileset_and_images_the_loader_opened(tmp_path: Path) -> None:
    tiny_png(tmp_path / "t.png")
    (tmp_path / "t.tsx").write_text(TILESET.format(
        image='<image source="t.png" width="64" height="16"/>').replace('firstgid="1" ', ""),
        encoding="utf-8")
    level = write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsx"/>')
    assert level_files(level) == [level, (tmp_path / "t.tsx").resolve(),
                                  (tmp_path / "t.png").resolve()]


def test_a_fifo_named_as_a_tileset_is_refused_at_once(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "t.tsx")
    level = write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsx"/>')
    game = run(["-m", "game", "--headless", "--ticks", "5", "--level", str(level)], tmp_path)
    assert game.returncode == 1
    assert "not a regular file" in one_sentence(game.stderr)


# -- the decoder's answer is the one checked --------------------------------------------------

def test_a_47_byte_gif_with_a_huge_frame_after_a_stray_byte_is_refused(tmp_path: Path) -> None:
    assert len(HOSTILE_GIF) == 47
    assert header_size(HOSTILE_GIF) == ("GIF", 65535, 65535)
    (tmp_path / "t.gif").write_bytes(HOSTILE_GIF)
    level = write_map(tmp_path, tileset=TILESET.format(
        image='<image source="t.gif" width="16" height="16"/>'))
    done = run(["-m", "game.levels", "check", str(level), "--no-solve"], tmp_path)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    [line] = [line for line in done.stdout.splitlines() if "t.gif" in line]
    assert "65535x65535 GIF" in line and "16384 pixels a side" in line
    game = run(["-m", "game", "--ticks", "1", "--level", str(level)], tmp_path)
    assert game.returncode == 1 and "65535x65535" in one_sentence(game.stderr)


def test_a_gif_frame_placed_past_its_screen_counts_where_it_ends() -> None:
    gif = (b"GIF89a" + struct.pack("<HH", 16, 16) + b"\0\0\0"
           + b"," + struct.pack("<HHHHB", 10, 0, 16, 16, 0) + b"\x02\x02\x44\x01\0"
           + b"," + struct.pack("<HHHHB", 0, 0, 9000, 4, 0) + b"\x02\x02\x44\x01\0;")
    assert header_size(gif) == ("GIF", 9000, 16)


def test_a_png_named_gif_is_decoded_as_what_it_was_measured_as(tmp_path: Path) -> None:
    tiny_png(tmp_path / "t.png")
    (tmp_path / "t.png").rename(tmp_path / "t.gif")
    level = write_map(tmp_path, tileset=TILESET.format(
        image='<image source="t.gif" width="64" height="16"/>'), objects=OBJECTS)
    assert check_level(level).errors == []
