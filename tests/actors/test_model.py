from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.actors.model import (
    ActorFileError,
    ActorSet,
    Part,
    format_actors,
    parse_actors,
    read_actors,
    write_actors,
)
from tests.actors.strategies import actor_set

CHESS = Path(__file__).resolve().parents[2] / "examples" / "ca" / "chess.actors"


def test_chess_example_reads_with_four_chessmen() -> None:
    s = read_actors(CHESS)
    assert s.rules == "life"
    assert [a.name for a in s.actors.values()] == ["pawn", "knight", "rook", "king"]
    assert s.actors[1].parts[0].kind == "lathe"
    assert s.actors[1].cycles[0].kind == "bob"


def test_chess_example_round_trips_through_the_writer(tmp_path: Path) -> None:
    s = read_actors(CHESS)
    write_actors(tmp_path / "c.actors", s)
    assert read_actors(tmp_path / "c.actors") == s


@settings(max_examples=150, deadline=None)
@given(actor_set())
def test_any_actor_set_round_trips_exactly(s: ActorSet) -> None:
    assert parse_actors(format_actors(s), "x.actors") == s


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=300))
def test_any_text_is_parsed_or_refused_with_file_line_col(text: str) -> None:
    try:
        parse_actors("rules life\n" + text, "t.actors")
    except ActorFileError as exc:
        head = str(exc).split(": ", 1)[0].split(":")
        assert head[0] == "t.actors" and int(head[1]) >= 1 and int(head[2]) >= 1


GOOD = "rules life\nactor 1 p\n  colour 1 2 3\n  box 1 1 1\nend\n"


@pytest.mark.parametrize(("text", "where", "words"), [
    ("", "1:1", "must start with 'rules NAME'"),
    ("actor 1 p\n", "1:1", "must start with 'rules NAME'"),
    (GOOD.replace("colour 1 2 3", "colour 1 2"), "3:13", "expected blue"),
    (GOOD.replace("colour 1 2 3", "colour 1 2 300"), "3:14", "between 0 and 255"),
    (GOOD.replace("box 1 1 1", "box 1 one 1"), "4:9", "'one' is not a number"),
    (GOOD.replace("box 1 1 1", "box 1 1 0"), "4:11", "between"),
    (GOOD.replace("box 1 1 1", "box 1 1 1 at 0 0"), "4:19", "expected at z"),
    (GOOD.replace("box 1 1 1", "lathe 0.3 0 0.2 -1"), "4:19", "height -1 is below"),
    (GOOD.replace("box 1 1 1", "lathe 0.3 0"), "4:3", "at least 2"),
    (GOOD.replace("box 1 1 1", "extrude 0 0 1 0 1 1"), "4:22", "'height H'"),
    (GOOD.replace("box 1 1 1", "cone 1"), "4:3", "unknown keyword 'cone'"),
    (GOOD.replace("box 1 1 1", "box 1 1 1 inf"), "4:13", "unexpected 'inf'"),
    (GOOD.replace("box 1 1 1", "box nan 1 1"), "4:7", "between"),
    (GOOD.replace("box 1 1 1", "bob 0.1 0"), "4:11", "between 1 and"),
    (GOOD.replace("  box 1 1 1\n", ""), "4:1", "has no parts"),
    (GOOD.replace("  colour 1 2 3\n", ""), "4:1", "has no 'colour"),
    (GOOD.replace("end\n", ""), "2:1", "not closed by 'end'"),
    (GOOD + "actor 1 q\n", "6:7", "already has an actor"),
    (GOOD.replace("actor 1 p", "actor 1 p!"), "2:9", "is not a name"),
    (GOOD.replace("actor 1 p", "actor 256 p"), "2:7", "between 0 and 255"),
    (GOOD + "colour 1 2 3\n", "6:1", "outside an actor"),
    (GOOD.replace("colour 1 2 3", "material ambient 1 diffuse 1"), "3:31", "lacks specular"),
    (GOOD.replace("box 1 1 1", "box 1 1 1\n  face forward"), "5:8", "expected fixed or glide"),
])
def test_bad_files_are_refused_naming_line_and_column(text: str, where: str,
                                                      words: str) -> None:
    with pytest.raises(ActorFileError) as err:
        parse_actors(text, "bad.actors")
    assert str(err.value).startswith(f"bad.actors:{where}: "), str(err.value)
    assert words in str(err.value)


def test_comments_and_colour_spelling_are_accepted() -> None:
    s = parse_actors("# hello\nrules life # the rule set\nactor 1 p # a pawn\n color 1 2 3\n"
                     " sphere 0.3 at 0 0 0.1  # head\nend\n", "c.actors")
    assert s.actors[1].colour == (1, 2, 3)
    assert s.actors[1].parts == (Part("sphere", (), (0.3, 0.3, 0.3), (0, 0, 0.1)),)


def test_a_missing_file_and_bad_bytes_are_actor_file_errors(tmp_path: Path) -> None:
    with pytest.raises(ActorFileError, match="nope.actors"):
        read_actors(tmp_path / "nope.actors")
    bad = tmp_path / "b.actors"
    bad.write_bytes(b"rules life\n\xff\n")
    with pytest.raises(ActorFileError, match=r"b.actors:2:1: .*not UTF-8"):
        read_actors(bad)


def test_error_survives_pickling_for_worker_processes() -> None:
    import pickle

    e = ActorFileError.at("a.actors", 3, 4, "bad")
    back = pickle.loads(pickle.dumps(e))
    assert str(back) == "a.actors:3:4: bad" and back.line == 3


def test_a_failed_save_keeps_the_old_file(tmp_path: Path) -> None:
    path = tmp_path / "k.actors"
    s = read_actors(CHESS)
    write_actors(path, s)
    before = path.read_bytes()
    with pytest.raises(AttributeError):
        write_actors(path, ActorSet("life", {1: "not an actor"}))
    assert path.read_bytes() == before
