"""§7.3.2's breeder (Gosper's breeder 1, apps/ca/library/breeder.rle): its defining
behaviour is quadratic growth -- puffers lay glider guns, each gun adds gliders -- so the
population at a few generations must be Golly's, and doubling the time must about
quadruple what is added."""

from __future__ import annotations

import re
import subprocess

from camlab88.apps.ca import library
from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules
from tests.ca.golly_oracle import need_bgolly

# bgolly 3.3 on Golly's Patterns/Life/Breeders/breeder.lif (the file's source)
POPULATION = {0: 4060, 1000: 6427, 2000: 10746, 4000: 28342}


def test_breeder_population_grows_as_golly_says_and_quadratically() -> None:
    e = Engine(load_rules(library.rules_path("life")))
    xs, ys, ts = read_pattern(library.pattern_path("breeder")).placed(0, 0)
    e.set_cells(xs, ys, ts)
    seen = {0: e.population}
    for g in (1000, 2000, 4000):
        e.step(g - e.generation)
        seen[g] = e.population
    assert seen == POPULATION
    early = seen[2000] - seen[1000]
    late = seen[4000] - seen[2000]  # twice the time: four times the cells, near enough
    assert 3.6 < late / early < 4.4, (early, late)


def test_shipped_breeder_file_is_the_one_golly_counts() -> None:
    exe = need_bgolly()
    path = library.pattern_path("breeder")
    for g, want in POPULATION.items():
        r = subprocess.run([exe, "-m", str(g), str(path)], capture_output=True, text=True,
                           timeout=120, check=True)
        last = r.stdout.strip().splitlines()[-1]
        m = re.fullmatch(r"[\d,]+: ([\d,]+)", last)
        assert m is not None, r.stdout
        assert int(m.group(1).replace(",", "")) == want, (g, last)
