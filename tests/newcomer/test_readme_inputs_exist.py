"""Every file a README line reads exists before it runs: shipped in the repository, or
written by an earlier README line (the newcomer met `ca replay --script session.log` when
only `ca/session.log` had been made). Files a program makes when they are missing — a new
keyframe, camera script or cell-type file to edit — are named here, on purpose."""

from __future__ import annotations

import re
from pathlib import Path

from tests.newcomer.test_every_command_ends import placeholder
from tests.test_readme_walkthrough import every_command, written

ROOT = Path(__file__).resolve().parents[2]
INPUT = re.compile(r"[\w./-]+\.(kas|log|ccl|json|cp|checkpoint|views|session|sig|script|events|"
                   r"actors|ops|rle|cells|pat|txt|c88state|rec)$")
# opened for editing, made new when missing (the program says so)
MORE_OUTPUTS = ("--save-state", "--video", "--inspect-out", "--record-stream", "--ops-out")
NEW_ON_PURPOSE = {"my.ccl", "my_life.actors", "pawn.actors", "key.kas", "game.json", "s.log"}


def test_every_file_a_readme_line_reads_exists_or_an_earlier_line_made_it() -> None:
    made: set[str] = set()
    missing = []
    for argv in every_command((ROOT / "README.md").read_text(encoding="utf-8")):
        if placeholder(argv):
            continue
        out = {w.rstrip("/") for w in written(argv)} | {
            argv[i + 1] for i, w in enumerate(argv[:-1]) if w in MORE_OUTPUTS}
        for word in argv[1:]:
            name = word.split("@")[0]
            if (not INPUT.match(name) or name in out or name in made
                    or name in NEW_ON_PURPOSE or (ROOT / name).exists()):
                continue
            missing.append(f"{' '.join(argv)}: {name}")
        made |= out
    assert not missing, "\n".join(missing)
