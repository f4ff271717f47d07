"""§7.4.2: the prime-testing Turing machine stops at the thesis's digit-count bound, so it
tries O(sqrt N) divisors; the cellular automaton tries exactly the divisors the plain-tape
simulation of the same transition function tries."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.ca import turing
from camlab88.apps.ca.engine import Engine, Rect
from camlab88.apps.ca.rules import parse_rules

RULES = parse_rules(turing.rules_text())


def _is_prime(n: int) -> bool:
    return n > 1 and all(n % d for d in range(2, int(n ** 0.5) + 1))


def _ca_run(n: int, limit: int = 8000) -> tuple[str, list[int], int]:
    """Verdict, trial divisors (read off the second row) and generations in the CA."""
    forms = {t: v for v, t in turing.verdict_forms().items()}
    e = Engine(RULES)
    xs, ys, ts = turing.pattern(n).placed(500, 500)
    e.set_cells(xs, ys, ts)
    k = n.bit_length()
    row = Rect(501, 501, 500 + k, 501)
    weights = 1 << (500 + k - np.arange(501, 501 + k))
    best, divisors = 0, []
    while e.generation < limit:
        e.step()
        cx, _, ct = e.cells_in_rect(row)
        d = int(weights[cx[ct == turing.TAPE] - 501].sum())
        # INC's carry passes through smaller values; each new maximum is a new divisor
        if d > best:
            best = d
            if d >= 3:
                divisors.append(d)
        found = [forms[t] for t in e.by_type() if t in forms]
        if found:
            return found[0], divisors, e.generation
    raise AssertionError(f"no verdict for {n} in {limit} generations")


@pytest.mark.claim("§7.4.2: the machine stops when the divisor has more than half as many "
                   "significant digits as the number (no divisor squared can then divide "
                   "it)", measured="trial divisors counted: 3, 5, ... up to the first with "
                   "more than ceil(k/2) binary digits; 8 for N = 127 (63 to reach N)",
                   verdict="agrees (half rounded up: the literal 'more than half' would "
                   "call 121 = 11 x 11 prime)")
@pytest.mark.parametrize("n", [23, 53, 127])
def test_primes_try_only_divisors_up_to_the_digit_bound(n: int) -> None:
    verdict, divisors, _ = _ca_run(n)
    assert verdict == "YES"
    assert divisors == list(range(3, turing.trial_divisor_bound(n) + 1, 2))
    assert divisors == turing.simulate(n).divisors
    assert len(divisors) == 2 ** (-(-n.bit_length() // 2) - 1)  # ~ sqrt(N) / 2
    assert len(divisors) < (n - 1) // 2 - 1 or n < 10  # far fewer than up to N


@pytest.mark.parametrize("n,factor", [(25, 5), (121, 11), (9, 3)])
def test_composites_stop_at_their_smallest_odd_factor(n: int, factor: int) -> None:
    verdict, divisors, _ = _ca_run(n)
    assert verdict == "NO"
    assert divisors == list(range(3, factor + 1, 2)) == turing.simulate(n).divisors


@pytest.mark.claim("§7.4.2: a three-tape Turing machine, written as CA rules, recognises "
                   "prime numbers", measured="the plain-tape simulation of the machine's "
                   "transition function decides 1..400 correctly; the CA gives the same "
                   "verdicts (tests/ca/test_library.py, figure 7.9's 25 and others)")
def test_simulated_machine_decides_every_number_up_to_400() -> None:
    for n in range(1, 401):
        run = turing.simulate(n)
        assert (run.verdict == "YES") == _is_prime(n), n
        if _is_prime(n) and n > 2:
            assert run.divisors[-1] == turing.trial_divisor_bound(n), n


def test_steps_grow_like_sqrt_n_divisors_not_n() -> None:
    # For primes, the divisors tried double only when N gains two digits.
    small, big = turing.simulate(127), turing.simulate(8191)
    assert len(big.divisors) == 64 and len(small.divisors) == 8
    assert big.divisors[-1] ** 2 > 8191  # the bound is sound: no larger factor is needed
