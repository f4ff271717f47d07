"""Save states: each program's state file size and the time of the state operation itself
(``save_program`` / ``load_program`` as the state plugin calls them, timed in process; the
median of three save-then-load rounds). docs/performance.md ("Save states") holds the
figures, before and after issue 38.

Run by hand from the repository: ``python benchmarks/bench_states.py OUT.json SCRATCH_DIR``
(``ONLY="ca program,sigma run"`` for some programs). A program that saves no state is
reported with its refusal.
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # fuzz/ and tests/ helpers

from camlab88.emulator.harness import state_plugin as sp
from fuzz.states import run_cli
from tests.states.support import inputs_of

T: dict[str, list[float]] = {"save": [], "load": []}
real_save, real_load = sp.save_program, sp.load_program


def save(*a, **k):
    t = time.perf_counter()
    r = real_save(*a, **k)
    T["save"].append(time.perf_counter() - t)
    return r


def load(*a, **k):
    t = time.perf_counter()
    r = real_load(*a, **k)
    T["load"].append(time.perf_counter() - t)
    return r


sp.save_program, sp.load_program = save, load



def _median(v: list[float]) -> float:
    return sorted(v)[len(v) // 2] * 1000


d = Path(sys.argv[2])
d.mkdir(parents=True, exist_ok=True)
os.chdir(d)
inputs_of("examples/figures/fig-6.7.session", d)
inputs_of("examples/figures/fig-3.7.session", d)
inputs_of("tests/data/sessions/sigma_run.session", d)
run_cli(["kas", "demo", "--out", "seq.kas"], 300)
Path("e.events").write_text("frames 3\nclick middle 400 300\nframes 5\nclick right 300 300\n"
                            "frames 20\n")
Path("k.script").write_text("move 1 1\ndown 1 1\ndown 2 2\nup 2 2\nkey space\n")
run_cli(["kas", "edit", "k.kas", "--headless", "--script", "k.script"], 300)
P = {
 "sigma run": ["sigma", "run", "--headless", "--in", "picture.sigma", "--seconds", "2"],
 "rainbow run (pads)": ["rainbow", "run", "--headless", "--stop-after", "40"],
 "rainbow run (shelf)": ["rainbow", "run", "--headless", "--stop-after", "40", "--demo", "shelf"],
 "snooker play": ["snooker", "play", "--headless", "--events", "e.events"],
 "snooker replay": ["snooker", "replay", "pink_shot.cp", "--headless"],
 "snooker visualise": ["snooker", "visualise", "pink_shot.cp", "example.views", "--headless"],
 "ca program": ["ca", "program", "--headless", "--pattern", "gosper_gun", "--events", "e.events"],
 "kas view": ["kas", "view", "seq.kas", "--headless", "--every"],
 "kas edit": ["kas", "edit", "k.kas", "--headless", "--script", "k.script"],
 "kas paint": ["kas", "paint", "face.kas", "--headless", "--script", "fig-3.7.script"],
}
at = {"kas view": "0.5", "snooker replay": "1", "snooker visualise": "1", "sigma run": "1",
      "kas paint": "1", "kas edit": "0.5"}
out = {}
only = os.environ.get("ONLY")
for name, argv in P.items():
    if only and name not in only.split(","):
        continue
    for k in T:
        T[k].clear()
    runs = []
    for i in range(3):
        f = Path(f"m{i}.c88state")
        code, err = run_cli([*argv, "--save-state", str(f), "--at", at.get(name, "0.3")], 600)
        if code != 0 or not f.exists():
            out[name] = {"refused": err.strip().splitlines()[-1][:200]}
            break
        code, err = run_cli([*argv, "--load-state", str(f)], 600)
        runs.append(f.stat().st_size)
        if code != 0:
            out[name] = {"bytes": runs[0], "save_ms": round(T["save"][0] * 1000, 1),
                         "load": err.strip().splitlines()[-1][:200]}
            break
    if name in out:
        print(name, out[name], file=sys.stderr)
        continue
    out[name] = {"bytes": runs[0], "save_ms": round(_median(T["save"]), 1),
                 "load_ms": round(_median(T["load"]), 1)}
    print(name, out[name], file=sys.stderr)
Path(sys.argv[1]).write_text(json.dumps(out, indent=1))
