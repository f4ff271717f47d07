"""A state of an older version is read through the program's documented migration: the
stored ``kas view`` state of version 1 (tests/data/states, saved before the period was
renamed and bounded in version 2) loads and continues as the unbroken run; a version-1
state with other fields, and a version with no migration, are refused in one line naming
the file (and, for the version, both versions)."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.harness.sigma import PeriodTarget
from camlab88.emulator.machine.state_file import MachineStateError, pack, unpack
from tests.states.support import frame_logs, saved_place

DATA = Path(__file__).resolve().parents[1] / "data" / "states"
V1 = DATA / "kas_view_v1.c88state"
ARGV = ["kas", "view", str(DATA / "seq.kas"), "--headless", "--every"]


def _continues_as_unbroken(monkeypatch, argv: list[str], state: Path) -> None:
    """Loaded with ``argv``, the stored ``state`` shows every frame after its place as the
    run of ``argv`` that never saved."""
    with frame_logs(monkeypatch) as runs:
        assert main(argv) == 0
        assert main([*argv, "--load-state", str(state)]) == 0
    full, rest = runs
    k = saved_place(state)[1]
    full.pop("ticks"), rest.pop("ticks")
    assert rest and sorted(rest) == [n for n in sorted(full) if n > k]
    assert all(rest[n] == full[n] for n in rest)


def test_the_stored_state_is_of_version_1_and_this_kas_view_reads_version_2() -> None:
    head, _ = unpack(V1.read_bytes(), "program")
    assert head["state_version"] == 1 and set(head["values"]) == {"k", "machine"}
    assert PeriodTarget.STATE_VERSION == 2


def test_a_version_1_state_loads_through_the_migration_and_continues(monkeypatch) -> None:
    _continues_as_unbroken(monkeypatch, ARGV, V1)


def test_the_migration_renames_the_period_and_refuses_other_fields() -> None:
    assert PeriodTarget.migrate_state(1, {"k": 13, "machine": "b0"}) == {
        "period": 13, "machine": "b0"}
    for odd in ({"period": 13, "machine": "b0"}, {"k": 1}, ["k", "machine"], None):
        with pytest.raises(MachineStateError, match="version 1"):
            PeriodTarget.migrate_state(1, odd)


def _rewritten(tmp_path: Path, **changes) -> Path:
    head, parts = unpack(V1.read_bytes(), "program")
    head.update(changes)
    path = tmp_path / "s.c88state"
    path.write_bytes(pack("program", head, parts))
    return path


def test_a_version_1_state_with_other_fields_is_refused_in_one_line(tmp_path: Path) -> None:
    head, _ = unpack(V1.read_bytes(), "program")
    path = _rewritten(tmp_path, values={"period": 13, "machine": head["values"]["machine"]})
    with pytest.raises(SystemExit) as stop:
        main([*ARGV, "--load-state", str(path)])
    text = str(stop.value)
    assert str(path) in text and "its fields are not k and machine" in text
    assert "\n" not in text


def test_a_version_1_state_past_the_new_bound_is_refused(tmp_path: Path) -> None:
    head, _ = unpack(V1.read_bytes(), "program")
    path = _rewritten(tmp_path, values={"k": 1 << 41, "machine": head["values"]["machine"]})
    with pytest.raises(SystemExit, match=r"state\.period: .* is outside 0\.\."):
        main([*ARGV, "--load-state", str(path)])


@pytest.mark.parametrize("version", [3, 0])
def test_a_version_without_a_migration_is_refused_naming_both(tmp_path: Path,
                                                              version: int) -> None:
    path = _rewritten(tmp_path, state_version=version)
    with pytest.raises(SystemExit) as stop:
        main([*ARGV, "--load-state", str(path)])
    assert f"version {version}" in str(stop.value) and "version 2" in str(stop.value)


def test_a_ca_program_state_of_version_1_loads_without_a_dialogue(tmp_path: Path) -> None:
    """ca program's version 2 added the dialogue in progress; a version-1 state (which could
    not be saved in one) reads as having none."""
    events = tmp_path / "e.events"
    events.write_text("frames 3\nclick right 300 300\nframes 6\n")
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events", str(events)]
    state = tmp_path / "c.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.1"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    assert head["state_version"] == 5
    assert head["values"]["program"].pop("held_events") is None  # (version 5 added it)
    state.write_bytes(pack("program", dict(head, state_version=2), parts))
    assert main([*argv, "--load-state", str(state)]) == 0  # 2 -> 3: the same values
    assert head["values"]["program"].pop("dialogue") is None
    state.write_bytes(pack("program", dict(head, state_version=1), parts))
    assert main([*argv, "--load-state", str(state)]) == 0
    head["values"]["program"] = ["not", "a", "mapping"]
    state.write_bytes(pack("program", dict(head, state_version=1), parts))
    with pytest.raises(SystemExit, match="its program part is not a version-1 mapping"):
        main([*argv, "--load-state", str(state)])


CA_V3 = DATA / "ca_program_v3.c88state"
CA_ARGV = ["ca", "program", "--headless", "--pattern", "glider", "--events",
           str(DATA / "ca_populate.events")]


def _stored_ca_program(state: Path, version: int) -> dict:
    """The program values of a stored ``ca program`` state of ``version`` (an older one than
    this program's)."""
    from camlab88.apps.ca.program.program import CAProgram

    head, _ = unpack(state.read_bytes(), "program")
    assert head["state_version"] == version < CAProgram.STATE_VERSION
    return head["values"]["program"]


def test_the_stored_ca_program_state_is_of_version_3_inside_a_dialogue() -> None:
    dialogue = _stored_ca_program(CA_V3, 3)["dialogue"]
    assert dialogue["name"] == "Randomly populate" and "menu" not in dialogue


def test_a_ca_program_state_of_version_3_loads_and_continues(monkeypatch) -> None:
    """Version 4 added the dialogue's open choice menu: a version-3 state (which could not
    be saved with one open) reads as having none, and its dialogue goes on as the unbroken
    run's."""
    _continues_as_unbroken(monkeypatch, CA_ARGV, CA_V3)


def test_the_ca_program_migration_refuses_a_menu_in_an_older_dialogue() -> None:
    from camlab88.apps.ca.program.state import migrate

    values = {"dialogue": {"name": "Clear area", "answers": []}}
    assert migrate(3, values)["dialogue"]["menu"] is None
    assert migrate(2, {"dialogue": None}) == {"dialogue": None, "held_events": None}
    for version in (2, 3):
        with pytest.raises(ValueError, match=f"not a version-{version} mapping"):
            migrate(version, {"dialogue": dict(values["dialogue"], menu=None)})
        with pytest.raises(ValueError, match=f"not a version-{version} mapping"):
            migrate(version, {"engine": {}})


CA_V4 = DATA / "ca_program_v4.c88state"
CA_MENU_ARGV = ["ca", "program", "--headless", "--pattern", "glider", "--events",
                str(DATA / "ca_menu.events")]


def test_the_stored_ca_program_state_is_of_version_4_with_a_menu_open() -> None:
    values = _stored_ca_program(CA_V4, 4)
    assert "held_events" not in values
    assert values["dialogue"]["name"] == "Alter display" and values["dialogue"]["menu"]["open"]


def test_a_ca_program_state_of_version_4_loads_and_continues(monkeypatch) -> None:
    """Version 5 added the input held during a jump: a version-4 state (which could not be
    saved with any held) reads as holding none; its open choice menu is picked from as in
    the unbroken run."""
    _continues_as_unbroken(monkeypatch, CA_MENU_ARGV, CA_V4)


def test_the_ca_program_migration_from_4_holds_no_input_and_refuses_a_held_field() -> None:
    from camlab88.apps.ca.program.state import migrate

    menu = {"highlighted": 1, "open": True, "scroll": 0, "x": 241, "y": 129}
    values = {"dialogue": {"name": "Alter display", "answers": [], "menu": menu}}
    moved = migrate(4, values)
    assert moved["held_events"] is None and moved["dialogue"]["menu"] == menu
    for version in (1, 2, 3, 4):
        with pytest.raises(ValueError, match=f"not a version-{version} mapping"):
            migrate(version, {"dialogue": None, "held_events": None})
    with pytest.raises(ValueError, match="no migration from version 5"):
        migrate(5, values)
