"""README's "First ten minutes": its commands, taken from README.md itself (so the two
cannot drift), run in order in a fresh directory, headless, each succeeding, writing the
files it names for the next into its block's own directory, and changing no file an earlier
command made. And over the whole README: no two commands write the same file."""

from __future__ import annotations

import hashlib
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SECTION = "## First ten minutes"
OUTPUT_OPTIONS = ("--out", "--save-session", "--path-out", "--timing-out", "--png", "--log",
                  "--bands", "--pdf", "--svg", "--hpgl", "--frames", "--gif", "--mp4",
                  "--screenshot", "--record", "--record-line", "--save")
# written by two README lines on purpose: the CA program's Log continued by a later session
# ("carry on, same log continued") and the same command shown in its section-7.3.1 form
SHARED_ON_PURPOSE = {"s.log"}


def _section(readme: str) -> str:
    start = readme.index(SECTION + "\n")
    end = readme.find("\n## ", start + len(SECTION))
    return readme[start:end if end >= 0 else len(readme)]


def walkthrough_commands(readme: str) -> list[list[str]]:
    """The indented `camlab88 ...` lines of the section, in order, split as a shell would."""
    return [shlex.split(line.strip(), comments=True) for line in _section(readme).splitlines()
            if line.startswith("    camlab88 ")]


def walkthrough_directories(readme: str) -> list[str]:
    """The directories the section's `mkdir -p` lines make (one per block)."""
    return [d for line in _section(readme).splitlines() if line.startswith("    mkdir -p ")
            for d in shlex.split(line.strip())[2:]]


def every_command(readme: str) -> list[list[str]]:
    """Every indented `camlab88 ...` line of the whole README, split as a shell would."""
    text = readme.replace("\\\n", " ")  # a command continued on the next line
    return [shlex.split(line.strip(), comments=True) for line in text.splitlines()
            if line.startswith("    camlab88 ")]


def written(argv: list[str]) -> list[str]:
    """What a README line writes: its output options' files, `kas export`'s and `ca
    convert`'s second file, and a `kas library --save` entry (as library:NAME)."""
    if argv[1:3] == ["kas", "library"]:
        save = argv.index("--save") if "--save" in argv else None
        return [f"library:{argv[save + 2]}"] if save is not None else []  # --save FILE NAME
    out = _outputs(argv)
    if argv[1:3] in (["kas", "export"], ["ca", "convert"]):
        out.append(argv[4])
    return [p.rstrip("/") for p in out if p.upper() != p]  # not the placeholders (DIR, PNG)


def _camlab88() -> list[str]:
    script = Path(sys.executable).with_name("camlab88")
    return [str(script)] if script.exists() else [sys.executable, "-m", "camlab88"]


def _outputs(argv: list[str]) -> list[str]:
    """Files named by output options (not a count, as `kas inbetween --frames 7` is)."""
    return [argv[i + 1] for i, a in enumerate(argv[:-1])
            if a in OUTPUT_OPTIONS and not argv[i + 1].isdigit()]


def test_the_section_lists_the_whole_tour() -> None:
    commands = walkthrough_commands((ROOT / "README.md").read_text(encoding="utf-8"))
    areas = {argv[1] for argv in commands}
    assert {"sigma", "rainbow", "kas", "snooker", "ca"} <= areas
    assert len(commands) >= 15


def test_the_walkthrough_runs_in_order(tmp_path: Path) -> None:
    commands = walkthrough_commands((ROOT / "README.md").read_text(encoding="utf-8"))
    shutil.copytree(ROOT / "examples", tmp_path / "examples")  # the README's relative paths
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.update(SDL_VIDEODRIVER="dummy", CAMLAB88_KAS_LIBRARY=str(tmp_path / "library"),
               XDG_DATA_HOME=str(tmp_path / "data"))
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = walkthrough_directories(readme)
    assert {"sigma", "kas", "snooker", "ca"} <= set(blocks)
    for d in blocks:
        (tmp_path / d).mkdir(parents=True, exist_ok=True)
    made: dict[Path, str] = {}
    for argv in commands:
        done = subprocess.run(_camlab88() + argv[1:], cwd=tmp_path, env=env, text=True,
                              capture_output=True, timeout=300)
        shown = " ".join(argv)
        assert done.returncode == 0, f"{shown}\n{done.stdout}\n{done.stderr}"
        assert "Traceback" not in done.stderr, f"{shown}\n{done.stderr}"
        for name in _outputs(argv):
            assert (tmp_path / name).exists(), f"{shown} did not write {name}"
            assert Path(name).parts[0] in blocks, f"{shown} writes {name} outside its block"
        changed = [p for p, digest in made.items() if _digest(p) != digest]
        assert not changed, f"{shown} overwrote {changed}"
        made.update({p: _digest(p) for p in _files(tmp_path)})
    assert (tmp_path / "library" / "my_arc.kas").is_file()  # kas library --save kept it
    assert (tmp_path / "kas" / "plots" / "sequence.pdf").is_file()
    assert (tmp_path / "kas" / "house_sun.gif").stat().st_size > 0
    # and again, in the same directory with the same library (a second try, or a second
    # person on a shared HOME): every line still runs
    for argv in commands:
        done = subprocess.run(_camlab88() + argv[1:], cwd=tmp_path, env=env, text=True,
                              capture_output=True, timeout=300)
        shown = " ".join(argv)
        assert done.returncode == 0, f"second run: {shown}\n{done.stdout}\n{done.stderr}"
    # the examples themselves are inputs only: nothing in the walkthrough rewrote them
    for shipped in (ROOT / "examples").rglob("*"):
        if shipped.is_file():
            copy = tmp_path / "examples" / shipped.relative_to(ROOT / "examples")
            assert copy.read_bytes() == shipped.read_bytes(), copy


def _files(root: Path) -> list[Path]:
    return [p for p in root.rglob("*") if p.is_file() and "examples" not in p.parts]


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else "gone"


def test_no_two_readme_commands_write_the_same_file() -> None:
    """Following the README in order never overwrites an earlier block's results."""
    writers: dict[str, set[str]] = {}
    for argv in every_command((ROOT / "README.md").read_text(encoding="utf-8")):
        for path in written(argv):
            writers.setdefault(path, set()).add(" ".join(argv))
    clashes = {p: w for p, w in writers.items() if len(w) > 1 and p not in SHARED_ON_PURPOSE}
    assert not clashes, clashes
