"""Real host software: PGPLOT 5.2.2's own /GOC driver's streams (tests/data/sigma/pgplot,
SOURCES.md there) against PGPLOT's own /GIF pictures of the same pages, its cursor
exchange, and our model of the driver (protocols.sigma.drivers.PgplotGoc) byte for byte."""

from __future__ import annotations

import re
from fractions import Fraction

import numpy as np
import pytest

from camlab88 import Sigma
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.link.recording import read_recording
from camlab88.protocols.link.replay import replay_into
from camlab88.protocols.sigma.drivers import PgplotGoc
from tests.sigma.pgplot_data import DATA, STREAMS, gif_page, pages, recall_precision, stream

PAGES = [(name, k) for name in STREAMS for k in range(1, len(pages(name)) + 1)]
# Where PGPLOT drew a different picture for the GIF than for the Sigma (the README's table):
DIFFERENT_PICTURE = {
    ("pgdemo2", 4): "thick dashed lines: PGPLOT strokes thick lines 0.005 in apart, 0.384 px "
                    "on the GOC and 0.425 px in the GIF, so strokes and dash phase differ "
                    "on the host side",
}


def _render(page: bytes) -> Terminal:
    term = Terminal()
    term.feed(page)
    return term


@pytest.mark.parametrize(("name", "k"), PAGES)
def test_every_pgplot_page_decodes_with_no_unknown_or_malformed_order(name, k):
    s = _render(pages(name)[k - 1]).stats
    assert (s["unknown"], s["malformed"], s["errors"]) == (0, 0, 0), s


@pytest.mark.parametrize(("name", "k"), PAGES)
def test_every_pgplot_page_matches_pgplots_own_picture_within_1px(name, k):
    lit = _render(pages(name)[k - 1]).frame().any(axis=2)
    recall, precision = recall_precision(name, gif_page(name, k), lit)
    floor = 0.90 if (name, k) in DIFFERENT_PICTURE else 0.95
    assert recall >= floor and precision >= floor, (name, k, recall, precision)


def test_the_named_exception_really_is_below_the_bar():
    """So the exception list cannot outlive its reason."""
    for (name, k), _why in DIFFERENT_PICTURE.items():
        lit = _render(pages(name)[k - 1]).frame().any(axis=2)
        assert min(recall_precision(name, gif_page(name, k), lit)) < 0.95


def test_a_one_page_pgplot_stream_shows_no_alpha_text():
    """The driver opens with the alpha erase +-*/GJ BH FF +-*/ BH, before its GH: the flag
    right after FF must be recognised, else +-*/BH stays on the alpha screen."""
    term = _render(stream("goctest"))
    assert not term.alpha.chars.any()
    lit = term.frame().any(axis=2)
    assert recall_precision("goctest", gif_page("goctest", 1), lit) == (1.0, 1.0)


def _cursor_exchange() -> tuple[Sigma, bytes, bytes]:
    """Replay PGPLOT's side of the real exchange; strike A where the real user's crosshair
    was. Returns the Sigma, what it answered, and what the real exchange answered."""
    rec = read_recording(DATA / "cursor_exchange.rec")
    sigma = Sigma()
    replay_into(rec, sigma.machine.line.host, ">")
    prompt_end = next(t for t, d in rec.arrivals(">") if d.endswith(b"CFHF"))
    sigma.machine.run_until(prompt_end + Fraction(1, 100))
    assert sigma.machine.terminal.reg.cursor_report  # HF has armed the report
    sigma.cursor(468, 356)
    sigma.key("A")
    sigma.run()
    return sigma, sigma.received(), rec.stream("<")


def _grgo11_parse(reply: bytes) -> tuple[str, int, int]:
    """How GRGO11 reads its 9 bytes: key, 3 digits of x, a separator, 3 of y, CR."""
    assert len(reply) == 9 and reply[8:] == b"\r", reply
    return chr(reply[0]), int(reply[1:4]), int(reply[5:8])


def test_the_cursor_exchange_replays_and_pgplot_parses_the_reply():
    sigma, reply, real = _cursor_exchange()
    assert reply == real == b"A468,356\r"
    assert _grgo11_parse(reply) == ("A", 468, 356)  # PGPLOT printed CURSOR 6.262 7.458 CH=[A]
    assert sigma.problems == [] and sigma.stats["unknown"] == 0


def test_the_stray_b_after_a_cursor_read_is_dropped_at_the_next_flag():
    """The trailer +-*/CECBGJB (GCEND*11 loses the final H) leaves a B pending; the next
    buffer begins with the flag, which starts afresh: no unknown order, no trace warning."""
    sigma, _reply, _real = _cursor_exchange()
    sigma.send(b"+-*/GJGI200200GJ300300BH")
    sigma.run()
    assert sigma.stats["unknown"] == 0 and sigma.problems == []
    dropped = [ev for ev in sigma.trace if ev.order == "dropped"]
    assert [ev.args for ev in dropped] == [{"letter": "B"}]
    assert sigma.screen[511 - 150, 150].any()  # and the line after it is drawn


# ---------------------------------------------------------------- the driver model
_INIT = b"\r\n+-*/DD000CBGAAAHE999CK1GHBH"
_ERASE_ALPHA = b"+-*/GJBH\x0c+-*/BH"
_PROMPT = re.compile(rb"\+-\*/GICECA(\d{3})(\d{3})CFHF")
_FULL = PgplotGoc.BUFFER_BYTES - PgplotGoc.FLUSH_WITHIN  # a buffer this long flushes itself


def _calls(data: bytes) -> list[tuple]:
    """The driver calls a real stream shows (an explicit flush only where a buffer ended
    before the driver's own rule would have flushed it)."""
    calls: list[tuple] = []
    i, last = 0, None
    while i < len(data):
        for lit, call in ((_INIT, "init"), (_ERASE_ALPHA, "erase_alpha"),
                          (PgplotGoc.CURSOR_END, "after_cursor")):
            if data.startswith(lit, i):
                calls.append((call,))
                i += len(lit)
                break
        else:
            if m := _PROMPT.match(data, i):
                calls.append(("cursor_prompt", int(m[1]) - 100, int(m[2]) - 100))
                i = m.end()
                continue
            assert data.startswith(b"+-*/GJ", i), data[i:i + 20]
            end = data.index(b"BH", i)
            last = _buffer_calls(data[i + 6:end], calls, last)
            if end - i < _FULL:
                calls.append(("flush",))
            i = end + 2
    return calls


def _buffer_calls(body: bytes, calls: list[tuple], last: tuple | None) -> tuple | None:
    k = 0
    while k < len(body):
        two = body[k:k + 2]
        if two in (b"DA", b"FA", b"FB"):
            calls.append(("erase",) if two == b"DA" else ("colour", int(two == b"FA")))
            k += 2
            continue
        if two == b"GI":
            last, k = (int(body[k + 2:k + 5]) - 100, int(body[k + 5:k + 8]) - 100), k + 10
        x, y = int(body[k:k + 3]) - 100, int(body[k + 3:k + 6]) - 100
        calls.append(("line", *last, x, y))
        last, k = (x, y), k + 6
    return last


@pytest.mark.parametrize("name", [*STREAMS, "cursor_exchange"])
def test_the_driver_model_reproduces_the_real_drivers_bytes(name):
    real = (read_recording(DATA / "cursor_exchange.rec").stream(">")
            if name == "cursor_exchange" else stream(name))
    model = PgplotGoc()
    for call, *args in _calls(real):
        getattr(model, call)(*args)
    ours = model.finish()
    if ours != real:
        k = next((i for i, (a, b) in enumerate(zip(ours, real)) if a != b),
                 min(len(ours), len(real)))
        pytest.fail(f"{name}: first difference at byte {k}: model {ours[k - 20:k + 20]!r}, "
                    f"driver {real[k - 20:k + 20]!r}")


def test_a_full_buffer_flushes_itself_within_32_bytes_of_130():
    g = PgplotGoc()
    for i in range(20):
        g.line(i, 0, i, 100)  # 16 bytes each: GI xxxyyy GJ xxxyyy
    buffers = re.findall(rb"\+-\*/GJ(.*?)BH", g.finish())
    assert [len(b) + 6 for b in buffers[:-1]] == [102] * (len(buffers) - 1)
    assert np.all([len(b) + 6 < 130 for b in buffers])
