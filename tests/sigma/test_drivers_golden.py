"""Golden images of streams formed as PGPLOT GOC and RAL GKS form them, on both models."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.emulator.sigma import Terminal
from tests.sigma.helpers import DATA
from tests.sigma.streams import gks_plot, pgplot_plot, pgplot_session
from tests.support.golden import assert_matches_golden


@pytest.mark.parametrize("model", ["t5684", "t5688"])
def test_pgplot_goc_stream(model: str) -> None:
    data = pgplot_plot()
    assert data.startswith(b"\r\n+-*/DD000CBGAAAHE999CK1GHBH")
    t = Terminal(model)
    t.feed(data)
    assert t.stats["unknown"] == 0 and t.stats["malformed"] == 0
    assert_matches_golden(t.frame(), DATA / f"golden_pgplot_{model}.png")


@pytest.mark.parametrize("model", ["t5684", "t5688"])
def test_pgplot_cursor_prompt_is_answered(model: str) -> None:
    plot, prompt, after = pgplot_session()
    assert prompt == b"+-*/GICECA400400CFHF"
    t = Terminal(model)
    sent: list[bytes] = []
    t.on_output = sent.append
    t.feed(plot + prompt)
    assert t.reg.cursor_on and t.reg.cursor_report
    assert (t.reg.cursor_x, t.reg.cursor_y) == (300, 300)  # CE attached it to the pen
    t.cursor_keys(5, -2)
    t.key("A")
    assert sent == [b"A305,298\r"]
    t.feed(after)
    assert not t.reg.cursor_on and t.stats["unknown"] == t.stats["malformed"] == 0
    assert_matches_golden(t.frame(), DATA / f"golden_pgplot_{model}.png")


@pytest.mark.parametrize("model", ["t5684", "t5688"])
def test_ral_gks_stream(model: str) -> None:
    data = gks_plot(high_res=model == "t5688")
    assert data.startswith(b"\r+-*/HH" + bytes(10))
    assert data.endswith(b"HF")
    t = Terminal(model)
    sent: list[bytes] = []
    t.on_output = sent.append
    t.feed(data)
    assert t.stats["unknown"] == 0 and t.stats["malformed"] == 0
    assert t.reg.cursor_report and t.reg.cursor_on
    s = 2 if model == "t5688" else 1
    want = np.add.outer(np.arange(24), np.arange(48)) % 16  # the cell array, DJ rows
    assert (t.planes[30 * s:30 * s + 24 * s:s, 560 * s:560 * s + 48] == want).all()
    t.key("K")
    digits = 4 if model == "t5688" else 3
    assert sent == [b"K" + (b"0768,0512\r" if digits == 4 else b"384,256\r")]
    assert_matches_golden(t.frame(), DATA / f"golden_gks_{model}.png")
    if model == "t5688":
        t.feed(b"\r+-*/KQ4")
        assert_matches_golden(t.frame(), DATA / "golden_gks_t5688_half.png")


def test_gks_buffers_are_framed_cr_flag_and_cr_lf() -> None:
    data = gks_plot()
    bufs = data.split(b"\r\n")
    assert all(b.startswith(b"\r+-*/") for b in bufs[:-1] if b)
    assert max(len(b) for b in bufs) <= 200
