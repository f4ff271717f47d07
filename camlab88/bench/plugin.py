"""The camlab88 pytest plugin (entry point ``pytest11``): fixtures for testing host software
against the emulated devices, and the helpers such tests need (docs/api.md)."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

REGEN_OPTION = "--camlab88-regen"


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.getgroup("camlab88").addoption(
        REGEN_OPTION, action="store_true", default=False,
        help="write the golden PNGs camlab88_golden compares with (look at them, then commit)")


@pytest.fixture
def sigma() -> Any:
    """An in-process Sigma T5684 on a 9600-baud line, tracing every order."""
    from camlab88.bench.sigma import Sigma

    return Sigma()


@pytest.fixture
def rainbow() -> Any:
    """An in-process Rainbow with a pad-library client (``rainbow.client``)."""
    from camlab88.bench.rainbow import Rainbow

    return Rainbow()


@pytest.fixture
def sigma_pty(request: pytest.FixtureRequest) -> Iterator[Any]:
    """A running Sigma on a pseudo-terminal: ``.path`` to open, ``.terminal``, ``.sigma``,
    ``.screen()``, ``.wait_idle()``. Skips where there are no pseudo-terminals.  Options by
    indirect parametrisation, ``@pytest.mark.parametrize("sigma_pty", [{"strict": True}],
    indirect=True)``: ``model``, ``baud``, ``strict`` (the first unknown, malformed or
    out-of-range order raises ``camlab88.ProtocolError`` from ``wait_idle``/``wait_for``,
    or at the test's end), ``trace`` (False: no trace kept, faster)."""
    if os.name != "posix":
        pytest.skip("sigma_pty needs POSIX pseudo-terminals")
    from camlab88.bench.pty_sigma import PtySigma

    options = dict(getattr(request, "param", None) or {})
    unknown = set(options) - {"model", "baud", "strict", "trace"}
    if unknown:
        raise pytest.UsageError(f"sigma_pty: unknown option(s) {', '.join(sorted(unknown))} "
                                "(model, baud, strict, trace)")
    bench = PtySigma(**options)
    try:
        yield bench
    finally:
        bench.close()


@pytest.fixture
def assert_no_protocol_errors() -> Callable[[Any], None]:
    """``assert_no_protocol_errors(device)``: fail naming the first unknown, malformed,
    out-of-range or refused order the device saw."""

    def check(device: Any) -> None:
        sigma = getattr(device, "sigma", device)  # a sigma_pty bench or a Sigma / Rainbow
        problems = sigma.trace.problems
        if problems:
            raise AssertionError(f"{sigma.trace.problem_count} protocol error(s); the first: "
                                 f"{problems[0].message()}")

    return check


@pytest.fixture
def camlab88_golden(request: pytest.FixtureRequest) -> Callable[..., None]:
    """``camlab88_golden(screen, name, directory=None)``: the screen must equal
    ``<directory>/<name>.png`` (default: ``golden/`` beside the test file), exactly;
    ``pytest --camlab88-regen`` writes it instead — only there: a name with ``/`` or
    ``..``, an absolute name, or a symbolic link out of the directory is refused."""
    regen = bool(request.config.getoption(REGEN_OPTION, default=False))
    here = Path(str(request.node.fspath)).parent / "golden"

    def check(screen: Any, name: str, directory: str | os.PathLike[str] | None = None) -> None:
        from camlab88.bench.golden import compare_golden, golden_path

        compare_golden(screen, golden_path(Path(directory or here), name), regen)

    return check
