"""Every program's declared state schema against a snapshot (tests/states/state_schemas.json):
a schema that changes without its program's STATE_VERSION going up fails here, so a state
saved by an older camlab88 is never read as if its fields meant what they mean now.

After a deliberate change: raise the program's STATE_VERSION (and give it a
``migrate_state(version, values)`` if older states are to be read; otherwise they are
refused naming both versions), then run this file with ``CAMLAB88_UPDATE_SCHEMAS=1``."""

from __future__ import annotations

import json
import os
from pathlib import Path

from camlab88.base.plainstate import describe

SNAPSHOT = Path(__file__).with_name("state_schemas.json")


def schemas() -> dict[str, tuple[int, str]]:
    """program -> (state version, schema text), for every program that saves its state."""
    from camlab88.apps.ca.program.program import CAProgram
    from camlab88.apps.snooker.program.program import PositionReplay, Program
    from camlab88.apps.snooker.visualiser.program import Visualiser
    from camlab88.emulator.harness import program_state
    from camlab88.emulator.harness.rainbow import target_schema
    from camlab88.emulator.harness.sigma import PeriodTarget
    from camlab88.emulator.harness.sigma_line import SigmaLineTarget
    from camlab88.protocols.rainbow.demo import Demo
    from camlab88.protocols.rainbow.shelf import ShelfDemo

    rainbow = {"ca program": CAProgram, "snooker play": Program,
               "snooker replay": PositionReplay, "snooker visualise": Visualiser,
               "rainbow run (pads)": Demo, "rainbow run (shelf)": ShelfDemo}
    out = {name: (p.STATE_VERSION, describe(target_schema(p.STATE_SCHEMA)))
           for name, p in rainbow.items()}
    out["sigma run"] = (SigmaLineTarget.STATE_VERSION, describe(SigmaLineTarget.STATE_SCHEMA))
    out["kas view"] = (PeriodTarget.STATE_VERSION, describe(PeriodTarget.STATE_SCHEMA))
    out.update(_editors())
    # the envelope's own values (the harness's place, the time), in every program's file
    out["(envelope)"] = (1, f"harness {describe(program_state.PLACE)}, time "
                            f"{describe(program_state.TIME)}")
    return out


def _editors() -> dict[str, tuple[int, str]]:
    """The editors whose state is their input log (emulator.harness.input_log) and, where
    their file is rewritten as they run, what it held at the start."""
    from camlab88.commands.ca import actors
    from camlab88.commands.kas import edit
    from camlab88.commands.snooker import camera
    from camlab88.emulator.harness import input_log
    from camlab88.emulator.harness.rainbow import INPUT_STATE_VERSION as rainbow
    from camlab88.emulator.harness.sigma import SigmaProgramTarget
    from camlab88.emulator.harness.sigma_host import SigmaHostTarget

    with_start = input_log.program_schema
    sigma, host = SigmaProgramTarget.STATE_VERSION, SigmaHostTarget.STATE_VERSION
    return {"kas edit": (sigma, describe(with_start(edit.START))),
            "kas path": (sigma, describe(SigmaProgramTarget.STATE_SCHEMA)),
            "kas paint": (host, describe(SigmaHostTarget.STATE_SCHEMA)),
            "snooker camera": (rainbow, describe(with_start(camera.START))),
            "ca actors": (rainbow, describe(with_start(actors.START)))}


def test_no_schema_changes_without_its_version_going_up() -> None:
    now = {name: [v, text] for name, (v, text) in schemas().items()}
    if os.environ.get("CAMLAB88_UPDATE_SCHEMAS"):
        SNAPSHOT.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n")
    kept = json.loads(SNAPSHOT.read_text())
    assert sorted(now) == sorted(kept), "a program was added or removed: update the snapshot"
    for name, (version, text) in now.items():
        old_version, old_text = kept[name]
        if text != old_text:
            assert version > old_version, (
                f"{name}: its state schema changed but STATE_VERSION is still {version}")
        assert version >= old_version, f"{name}: STATE_VERSION went down"


def test_the_snapshot_is_current() -> None:
    """(A version raised with its schema: the snapshot must be made again, so the next
    change is measured against this one.)"""
    now = {name: [v, text] for name, (v, text) in schemas().items()}
    assert json.loads(SNAPSHOT.read_text()) == now, \
        "run with CAMLAB88_UPDATE_SCHEMAS=1 after raising the version"


def test_a_changed_schema_without_a_new_version_fails(monkeypatch) -> None:
    """(The check above can fail: a field renamed under the same version.)"""
    import sys

    monkeypatch.delenv("CAMLAB88_UPDATE_SCHEMAS", raising=False)
    me = sys.modules[__name__]
    real = me.schemas()
    name = "sigma run"
    version, text = real[name]
    monkeypatch.setattr(me, "schemas", lambda: dict(real, **{name: (version, text.replace(
        "commands", "orders"))}))
    try:
        test_no_schema_changes_without_its_version_going_up()
    except AssertionError as exc:
        assert "sigma run: its state schema changed but STATE_VERSION is still 1" in str(exc)
    else:
        raise AssertionError("a renamed field under the same version passed")
