"""Bad files through the readers the CLI calls (non-UTF-8 bytes, deep nesting, huge numbers,
a directory for a file, damaged headers): each gives the format's own error (a ValueError)
naming the file and where, quickly and with a short quote, never a traceback, unbounded work
or a silently wrong answer."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.ca.log import LogError, read_log_settings
from camlab88.apps.ca.patterns import PatternError, read_pattern
from camlab88.apps.ca.rules import RuleError, load_rules
from camlab88.apps.kas.files import KasFileError, load_keyframe
from camlab88.apps.snooker import checkpoint
from camlab88.apps.snooker.session import Session, SessionError
from camlab88.emulator.rainbow.scene import SceneError, load_scene
from camlab88.protocols.link.recording import RecordingError, read_recording
from camlab88.protocols.rainbow.recording import Recording
from camlab88.protocols.rainbow.recording import RecordingError as RainbowRecordingError

DATA = Path(__file__).parents[1] / "data"
LINK_OK = "camlab88-link-recording 1\nline 9600 8N1\nxonxoff on\n{t} > 2b2d2a2f48\nend 1\n"


def _write(tmp_path: Path, name: str, data: bytes | str) -> Path:
    p = tmp_path / name
    p.write_bytes(data.encode() if isinstance(data, str) else data)
    return p


def _raises(error: type[Exception], path: Path, reader, where: str = "") -> str:
    with pytest.raises(error) as info:
        reader(path)
    text = str(info.value)
    assert text.startswith(str(path) + where), text
    assert len(text) < 400, "an error must not quote the whole input"
    return text


# -- non-UTF-8 bytes --------------------------------------------------------------------
def test_non_utf8_rainbow_scene_names_line_and_column(tmp_path) -> None:
    p = _write(tmp_path, "s.json", b'{"lut": [\n [0, "\xff"]]}')
    assert "byte 0xff is not UTF-8" in _raises(SceneError, p, load_scene, ":2:7:")


def test_non_utf8_rainbow_recording(tmp_path) -> None:
    p = _write(tmp_path, "r.rec", b"# camlab88 rainbow recording v1\n> 00\xff\n")
    _raises(RainbowRecordingError, p, Recording.load, ":2:5:")


# -- deep nesting and huge numbers in JSON ------------------------------------------------
def test_a_scene_nested_100000_deep(tmp_path) -> None:
    p = _write(tmp_path, "deep.json", "[" * 100_000 + "]" * 100_000)
    assert "nested deeper" in _raises(SceneError, p, load_scene)


def test_a_5000_digit_integer_in_a_scene(tmp_path) -> None:
    p = _write(tmp_path, "big.json", '{"lut": [[1' + "0" * 5000 + ', "#000000"]]}')
    assert "5001 digits" in _raises(SceneError, p, load_scene)


def test_a_20_digit_scene_coordinate_is_outside_int32(tmp_path) -> None:
    scene = ('{"nodes": {"c": {"type": "cluster", "width": 10, "height": 10}}, "arcs": '
             '[{"parent": "screen", "child": "c", "x": 99999999999999999999}]}')
    assert "outside" in _raises(SceneError, _write(tmp_path, "x.json", scene), load_scene)


def test_snooker_session_nested_100000_deep(tmp_path) -> None:
    _raises(SessionError, _write(tmp_path, "s.json", "[" * 100_000), Session.load)


def test_snooker_session_ball_position_of_401_digits(tmp_path) -> None:
    data = Session.new_game().to_json()
    data["time_frames"][0]["balls"]["pos"][0][0] = 10**400
    p = _write(tmp_path, "s.json", json.dumps(data))
    assert "401 digits" in _raises(SessionError, p, Session.load)


# -- a link recording whose time is a 401-digit number ------------------------------------
def test_link_recording_time_of_401_digits(tmp_path) -> None:
    p = _write(tmp_path, "r.rec", LINK_OK.format(t="1" + "0" * 400))
    assert "characters long" in _raises(RecordingError, p, read_recording, ":4:")


def test_a_time_past_the_bound_is_refused(tmp_path) -> None:
    p = _write(tmp_path, "r.rec", LINK_OK.format(t="10000000000.0"))
    assert "may span" in _raises(RecordingError, p, read_recording, ":4:")


# -- a snooker checkpoint coordinate of 20 digits -----------------------------------------
def test_checkpoint_coordinate_of_20_digits(tmp_path) -> None:
    lines = (DATA / "snooker" / "thesis_example.cp").read_text().splitlines()
    lines[3] = "9" * 20 + ",5"
    p = _write(tmp_path, "c.cp", "\n".join(lines) + "\n")
    assert "outside 0..65535" in _raises(checkpoint.CheckpointError, p, checkpoint.read, ":4:")


# -- a directory given as a file ----------------------------------------------------------
@pytest.mark.parametrize("reader,error", [(read_pattern, PatternError), (load_rules, RuleError),
                                          (load_keyframe, KasFileError),
                                          (read_recording, RecordingError),
                                          (load_scene, SceneError)])
def test_a_directory_is_not_a_file(tmp_path, reader, error) -> None:
    d = tmp_path / "dir.rle"
    d.mkdir()
    assert "is a directory" in _raises(error, d, reader)


# -- CA numbers beyond what the format can mean -------------------------------------------
def test_ca_pattern_cell_at_20_digit_coordinates(tmp_path) -> None:
    p = _write(tmp_path, "p.pat", "CAMLAB88-CA-PATTERN 1\ncells 1\n" + "9" * 20 + " 1 1\nend\n")
    assert "65536-cell plane" in _raises(PatternError, p, read_pattern, ":3:")


def test_ca_log_seed_of_20_digits(tmp_path) -> None:
    p = _write(tmp_path, "l.log", "CAMLAB88-CA-LOG 1\nseed " + "9" * 20 + "\n")
    assert "outside" in _raises(LogError, p, read_log_settings, ":2:")


# -- work bounded by what the input can ask for ------------------------------------------
def test_a_render_of_a_recording_ending_at_10_to_the_8_s_is_refused() -> None:
    from camlab88.protocols.link.sniff import frame_count

    with pytest.raises(ValueError, match="2500000001 frames, more than 100000"):
        frame_count(Fraction(10**8), 25, name="r.rec")
    assert frame_count(Fraction(10**8), 25, limit=None) == 2_500_000_001


def test_a_snooker_frame_rate_of_10_to_the_9_is_refused(tmp_path) -> None:
    s = Session.new_game()
    data = s.to_json()
    data["table"]["frame_rate"] = 10**9
    with pytest.raises(SessionError, match="frame_rate 1000000000 is outside 1..1000"):
        Session.from_json(data)


# -- large legitimate patterns load (timing: docs/reliability.md) ------------------------
def test_a_4000_square_rle_and_a_3000_square_cells_load(tmp_path) -> None:
    rle = _write(tmp_path, "big.rle", "x = 4000, y = 4000\n" + "4000o$" * 3999 + "4000o!\n")
    p = read_pattern(rle)
    assert p.xs.size == 16_000_000 and (p.width, p.height) == (4000, 4000)
    assert p.xs[4001] == 1 and p.ys[4001] == 1
    cells = _write(tmp_path, "big.cells", ("O" * 3000 + "\n") * 3000)
    q = read_pattern(cells)
    assert q.xs.size == 9_000_000 and (q.width, q.height) == (3000, 3000)


# -- a damaged link recording is not drawn as raw Sigma bytes ----------------------------
def test_a_recording_with_a_bom(tmp_path) -> None:
    from camlab88.protocols.link.sniff import read_link_input

    p = _write(tmp_path, "r.rec", b"\xef\xbb\xbf" + LINK_OK.format(t="0.1").encode())
    assert "byte-order mark" in _raises(RecordingError, p, read_link_input, ":1:1:")


def test_a_recording_with_a_damaged_first_line(tmp_path) -> None:
    from camlab88.protocols.link.sniff import read_link_input

    p = _write(tmp_path, "r.rec", LINK_OK.format(t="0.1").replace("recording", "recordin"))
    assert "first line is damaged" in _raises(RecordingError, p, read_link_input, ":1:")


def test_raw_sigma_bytes_are_still_raw(tmp_path) -> None:
    from camlab88.protocols.link.sniff import read_link_input

    p = _write(tmp_path, "s.sig", b"+-*/BH\r\nAA100200\r\n")
    assert read_link_input(p) == b"+-*/BH\r\nAA100200\r\n"


# -- CA .pat coordinates do not wrap; a pattern wider than the plane is refused ----------
def test_cells_2_to_the_32_apart_do_not_wrap(tmp_path) -> None:
    p = _write(tmp_path, "w.pat", "CAMLAB88-CA-PATTERN 1\ncells 2\n0 0 1\n4294967296 4294967296 1\n"
                                  "end\n")
    assert "wider or taller" in _raises(PatternError, p, read_pattern, ":4:")


def test_a_pattern_wider_than_the_plane(tmp_path) -> None:
    p = _write(tmp_path, "w.pat", "CAMLAB88-CA-PATTERN 1\ncells 2\n0 0 1\n65536 0 1\nend\n")
    _raises(PatternError, p, read_pattern, ":4:")
    ok = _write(tmp_path, "ok.pat", "CAMLAB88-CA-PATTERN 1\ncells 2\n0 0 1\n65535 0 1\nend\n")
    assert read_pattern(ok).width == 65536


# -- messages: the file's name, a short quote ------------------------------------------------
def test_an_error_quoting_a_1_mb_line_is_short(tmp_path) -> None:
    p = _write(tmp_path, "l.log", "CAMLAB88-CA-LOG 1\n" + "x" * 1_000_000 + "\n")
    assert "1000000 characters" in _raises(LogError, p, lambda q: __import__(
        "camlab88.apps.ca.log", fromlist=["read_log"]).read_log(q), ":2:")


def test_snooker_session_errors_are_not_python_exception_text(tmp_path) -> None:
    s = Session.new_game()
    data = s.to_json()
    del data["time_frames"][0]["balls"]
    with pytest.raises(SessionError) as info:
        Session.from_json(data)
    assert "KeyError" not in str(info.value) and "missing 'balls'" in str(info.value)


def test_potted_balls_stay_in_the_16_bit_packing() -> None:
    """Potted balls are parked inside 0..65535 (never at negative coordinates), still off
    the playing area (§6.2.2)."""
    from camlab88.apps.snooker.table import Table

    table = Table()
    pos = np.full((22, 2), 0.5)
    pos[0] = table.pockets[0].drop  # the baulk-right pocket: below 0 on both axes
    cp = checkpoint.Checkpoint.from_metres([pos], (table.length_m, table.width_m))
    assert cp.positions.min() >= 0 and cp.positions.max() <= checkpoint.PACK_MAX
    x, y = checkpoint.to_metres(cp.positions[0, 0])
    assert not table.on_playing_area(x, y)
    assert np.array_equal(checkpoint.parse(cp.to_text()).positions, cp.positions)
