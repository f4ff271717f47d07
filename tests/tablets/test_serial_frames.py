"""Each serial protocol through a real pty opened with pyserial: published/computed frames,
split packets, garbage between packets, wrong parity."""

from __future__ import annotations

import pytest

from camlab88.protocols.tablets import wacom4
from camlab88.protocols.tablets.base import ProtocolError
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.framing import add_parity
from camlab88.protocols.tablets.registry import make_encoder, make_parser

# --- CalComp: the real captured DrawingBoard 23120 frame (hansake README) -------------------


def test_calcomp_real_frame(pty_pair) -> None:
    (event,) = pty_pair.through(make_parser("calcomp"), bytes.fromhex("bc 31 2d 00 2e 0f"))
    assert (event.x, event.y) == (6317, 5903)
    assert event.buttons == 0b1111  # all four buttons pressed
    assert event.proximity


def test_calcomp_edge_value_11999(pty_pair) -> None:
    # The README's right/top edge reading: high/low 7-bit pair 5d 5f = 11999.
    (event,) = pty_pair.through(make_parser("calcomp"), bytes.fromhex("80 5d 5f 00 5d 5f"))
    assert (event.x, event.y, event.buttons) == (11999, 11999, 0)


def test_calcomp_proximity_bit_is_configurable() -> None:
    frame = bytes.fromhex("84 01 00 20 01 00")  # byte 3 bit 5 set
    assert not make_parser("calcomp").feed(frame)[0].proximity  # XFree86 code: 0x20 = out
    assert make_parser("calcomp", {"prox_bit": "0x40"}).feed(frame)[0].proximity


# --- Wacom IV: frames computed in the facts from the kernel's layout ------------------------


def test_wacom4_computed_frames(pty_pair) -> None:
    parser = make_parser("wacom4")
    data = bytes.fromhex("E8 27 08 08 17 38 24") + bytes.fromhex("E0 77 08 00 77 08 40")
    first, second = pty_pair.through(parser, data)
    assert first == TabletEvent(5000, 3000, True, 1, 200, tool="pen")
    assert second == TabletEvent(15240, 15240, True, 0, 0, tool="pen")


def test_wacom4_puck_eraser_and_out_of_proximity() -> None:
    enc = make_encoder("wacom4")
    parser = make_parser("wacom4")
    puck = TabletEvent(100, 200, True, 0b0101, None, tool="puck")
    eraser = TabletEvent(100, 200, True, 0b0101, 17, tool="eraser")
    away = TabletEvent(0, 0, False, 0, None, tool="pen")
    out = parser.feed(enc.encode(puck) + enc.encode(eraser) + enc.encode(away))
    assert out == [puck, eraser, away]
    assert enc.encode(puck)[0] & 0x20 == 0  # stylus bit clear for a cursor


def test_wacom4_graphire_pressure_and_eraser_mask() -> None:
    identity = wacom4.parse_model_reply("~#ET-0405-R00 V1.1-0")
    parser = make_parser("wacom4")
    parser.identify(identity)
    assert (parser.extra_z_bits, parser.eraser_mask) == (2, 0x08)
    assert parser.model.max_x == 5103 and parser.model.lines_per_inch == 1016
    enc = wacom4.Wacom4Encoder(extra_z_bits=2, eraser_mask=0x08)
    event = TabletEvent(5103, 3711, True, 0b0001, 511, tool="pen")
    assert parser.feed(enc.encode(event)) == [event]


@pytest.mark.parametrize(
    ("reply", "code", "version"),
    [  # real replies quoted in TabletMagic's SerialDaemon.cpp
        ("~#CT-0045R00,V1.3-5,", "CT", (1, 3)),
        ("~#GD-1212-R00,V1.2-7", "GD", (1, 2)),
        ("~#PL-400-R00 V1.3-3,", "PL", (1, 3)),
        ("~#420,V3.0-01,9C9D,", "42", (3, 0)),
        ("~#SD51C,V3.2.1.01,7000,", "SD", (3, 2)),
    ],
)
def test_wacom4_model_replies(reply: str, code: str, version: tuple[int, int]) -> None:
    identity = wacom4.parse_model_reply(reply)
    assert (identity.code, identity.version) == (code, version)


def test_wacom4_ud_old_rom_has_7_bit_pressure() -> None:
    assert wacom4.parse_model_reply("~#UD-1212-R00 V1.2-1").extra_z_bits == 0
    assert wacom4.parse_model_reply("~#UD-1212-R00 V1.4-4").extra_z_bits == 1


def test_wacom4_replies_interleaved_with_packets(pty_pair) -> None:
    parser = make_parser("wacom4")
    packet = bytes.fromhex("E8 27 08 08 17 38 24")
    data = b"~C15240,15240\r" + packet + b"~#CT-0045R00,V1.3-5," + packet
    events = pty_pair.through(parser, data)
    assert len(events) == 2
    # the PenPartner reply has no CR: it ends when the next packet's sync byte arrives
    texts = [r.text for r in parser.take_replies()]
    assert texts == ["~C15240,15240", "~#CT-0045R00,V1.3-5,"]
    assert wacom4.parse_coords_reply(texts[0]) == (15240, 15240)


def test_wacom4_reply_without_cr_is_taken_on_flush() -> None:
    parser = make_parser("wacom4")
    parser.feed(b"~#CT-0045R00,V1.3-5,")
    assert parser.take_replies() == []
    parser.flush()
    assert [r.text for r in parser.take_replies()] == ["~#CT-0045R00,V1.3-5,"]


def test_wacom4_settings_reply() -> None:
    settings = wacom4.parse_settings_reply("~RE202C900,002,02,1270,1270")
    assert settings.command_set == "wacom4"
    assert (settings.baud, settings.parity, settings.data_bits) == (9600, "N", 8)
    assert (settings.res_x, settings.res_y, settings.packet_length) == (1270, 1270, 7)
    tilted = wacom4.parse_settings_reply(settings.reply_text().replace("C900", "C910"))
    assert tilted.tilt and tilted.packet_length == 9
    with pytest.raises(ProtocolError):
        wacom4.parse_settings_reply("~R nonsense")


def test_wacom4_tilt_packets() -> None:
    enc = make_encoder("wacom4", {"tilt": "1"})
    parser = make_parser("wacom4", {"tilt": "1"})
    event = TabletEvent(7, 9, True, 1, 128, -64, 63, "pen")
    data = enc.encode(event)
    assert len(data) == 9 and data[7] == 0x40 and data[8] == 0x3F
    assert parser.feed(data) == [event]


# --- Summagraphics MM / Flair: computed from the XFree86 layout -----------------------------


def test_summa_mm_computed_frame(pty_pair) -> None:
    # X = 1000 = 0x3E8 -> low 7 bits 0x68, high 0x07; Y = 2000 -> 0x50, 0x0F; button code 1.
    frame = bytes((0x80 | 0x18 | 1, 0x68, 0x07, 0x50, 0x0F))
    (event,) = pty_pair.through(make_parser("summa-mm"), frame)
    assert (event.x, event.y, event.proximity, event.buttons) == (1000, 2000, True, 1)
    out = make_parser("summa-mm").feed(bytes((0xC0 | 0x18, 0, 0, 0, 0)))
    assert not out[0].proximity  # bit 6 set = OUT of proximity


def test_summa_button_code_versus_mask() -> None:
    frame = bytes((0x98 | 3, 1, 0, 1, 0))
    assert make_parser("summa-mm").feed(frame)[0].buttons == 0b100  # code 3 = third button
    assert make_parser("summa-mm", {"buttons": "mask"}).feed(frame)[0].buttons == 0b011


def test_summa_flair_pressure_and_controller() -> None:
    parser = make_parser("summa-mm", {"flair": "1"})
    # Z = 0b1_0110_1011 (363): b5 = Z8..Z2 = 0x5A, b6 bit0 = Z1 = 1, bit4 = Z0 = 1, type 01 pen
    frame = bytes((0x99, 1, 0, 1, 0, 0x5A, 0x10 | 0x04 | 0x02 | 0x01))
    (event,) = parser.feed(frame)
    assert (event.pressure, event.tool, event.buttons) == (363, "pen", 1)


# --- Bit Pad One / Two: ASCII ---------------------------------------------------------------


def test_bitpad2_ascii_report_with_parity(pty_pair) -> None:
    parser = make_parser("bitpad2")  # 7E1 read as 8N1: bit 7 is the parity bit
    line = bytes(add_parity(b, "E") for b in b"0124,2248,3\r\n")
    (event,) = pty_pair.through(parser, line)
    assert (event.x, event.y, event.buttons, event.proximity) == (124, 2248, 0b100, True)
    (away,) = parser.feed(bytes(add_parity(b, "E") for b in b"0124,2248,9\r\n"))
    assert not away.proximity and (away.x, away.y) == (124, 2248)


def test_bitpad1_perq_report(pty_pair) -> None:
    parser = make_parser("bitpad1")
    (event,) = pty_pair.through(parser, b"1234,0567,2\n")
    assert (event.x, event.y, event.buttons) == (1234, 567, 1)  # table index 1 -> '2'
    assert make_parser("bitpad1").feed(b"0000,2200,0\n")[0].buttons == 0
    # the emulated Bit Pad One writes the PERQ's form: four digits each, the flag, a LF
    assert make_encoder("bitpad1").encode(TabletEvent(1234, 567, True, 1, tool="puck")) \
        == b"1234,0567,2\n"


def test_calcomp_is_1000_lines_per_inch_with_its_origin_lower_left() -> None:
    m = make_parser("calcomp").model
    assert (m.max_x, m.max_y, m.lines_per_inch, m.origin) == (11999, 11999, 1000.0,
                                                               "lower-left")


def test_bit_pads_are_11_inches_square_at_200_lines_per_inch() -> None:
    for name in ("bitpad1", "bitpad2"):
        m = make_parser(name).model
        assert (m.max_x, m.max_y, m.lines_per_inch, m.origin) == (2200, 2200, 200.0,
                                                                   "lower-left")


# --- robustness, every protocol -------------------------------------------------------------

SAMPLES = {
    "wacom4": [TabletEvent(5000, 3000, True, 1, 200), TabletEvent(1, 2, True, 0, 0)],
    "summa-mm": [TabletEvent(1000, 2000, True, 1), TabletEvent(3, 4, True, 0)],
    "bitpad1": [TabletEvent(1000, 2000, True, 1, tool="puck"), TabletEvent(3, 4, True, 0,
                                                                           tool="puck")],
    "bitpad2": [TabletEvent(1000, 2000, True, 1, tool="puck"), TabletEvent(3, 4, True, 0,
                                                                           tool="puck")],
    "calcomp": [TabletEvent(6317, 5903, True, 15, tool="puck"), TabletEvent(3, 4, True, 0,
                                                                            tool="puck")],
}


@pytest.mark.parametrize("name", sorted(SAMPLES))
def test_split_anywhere_through_pty(pty_pair, name: str) -> None:
    enc = make_encoder(name)
    data = b"".join(enc.encode(e) for e in SAMPLES[name])
    parser = make_parser(name)
    events = []
    for k in range(len(data)):  # one byte per write, read back before the next
        events += pty_pair.through(parser, data[k : k + 1])
    assert events == SAMPLES[name]


@pytest.mark.parametrize("name", sorted(SAMPLES))
def test_garbage_between_packets(pty_pair, name: str) -> None:
    enc = make_encoder(name)
    a, b = (enc.encode(e) for e in SAMPLES[name])
    if name.startswith("bitpad"):
        noise = enc.encode(SAMPLES[name][0])[:5] + b"\r" + bytes(
            add_parity(c, "E" if name == "bitpad2" else "N") for c in b"#x!,9\r\n")
    else:
        noise = b"\x11\x05\x7f" + a[:3]  # line noise, then a packet cut short
    parser = make_parser(name)
    events = pty_pair.through(parser, noise + a + noise + b + noise)
    assert events == SAMPLES[name]
    assert parser.stats.dropped_bytes + parser.stats.bad_packets > 0


def test_bitpad2_wrong_parity_drops_only_that_report(pty_pair) -> None:
    parser = make_parser("bitpad2")
    good = bytes(add_parity(b, "E") for b in b"0100,0200,0\r\n")
    bad = bytearray(bytes(add_parity(b, "E") for b in b"0300,0400,1\r\n"))
    bad[2] ^= 0x80  # one character with the wrong parity
    events = pty_pair.through(parser, good + bytes(bad) + good)
    assert [(e.x, e.y) for e in events] == [(100, 200), (100, 200)]
    assert parser.stats.parity_errors == 1


@pytest.mark.parametrize("name", ["summa-mm", "calcomp", "wacom4"])
def test_parity_error_marked_by_the_os_spoils_the_packet(pty_pair, name: str) -> None:
    # An 8-bit line with parity (Summagraphics 8O1) cannot carry the parity bit through a pty;
    # the serial driver with INPCK|PARMRK delivers a bad byte as FF 00 <byte>.  Inject that.
    enc = make_encoder(name)
    a, b = (enc.encode(e) for e in SAMPLES[name])
    spoilt = a[:2] + b"\xff\x00" + a[2:]
    parser = make_parser(name, parmrk=True)
    events = pty_pair.through(parser, spoilt + b)
    assert events == SAMPLES[name][1:]
    assert parser.stats.parity_errors == 1


def test_out_of_range_event_is_refused() -> None:
    with pytest.raises(ProtocolError):
        make_encoder("summa-mm").encode(TabletEvent(20000, 0))
    with pytest.raises(ProtocolError):
        make_encoder("bitpad2").encode(TabletEvent(1, 1, True, 0b11))
    with pytest.raises(ValueError, match="unknown tablet protocol"):
        make_parser("nope")


def test_line_setups() -> None:
    from camlab88.protocols.tablets.line_setup import line_setup

    wacom = line_setup("wacom4")
    assert (wacom.baud, wacom.wire, wacom.rtscts) == (9600, (8, "N", 1), True)
    assert [s.baud for s in wacom.init if s.baud] == [38400, 19200, 9600]
    assert wacom.init[0].data == b"\r$" and wacom.init[1].data == b"\r#"
    summa = line_setup("summa-mm")
    assert (summa.wire, summa.xoff_to_tablet, summa.software_parity) == ((8, "O", 1), True, "N")
    assert summa.init[0].data == b" " * 10 + b"\x00" and summa.init[0].wait == 0.4
    bp2 = line_setup("bitpad2")  # 7E1 is opened as 8N1 with parity checked in software
    assert (bp2.data_bits, bp2.parity, bp2.wire, bp2.software_parity) == (7, "E", (8, "N", 1),
                                                                          "E")
    cal = line_setup("calcomp")
    assert (cal.wire, cal.xoff_to_tablet, cal.rtscts) == ((8, "N", 1), False, False)
    with pytest.raises(ValueError, match="unknown tablet protocol"):
        line_setup("mouse")


def test_wacom4_model_reply_version_is_after_the_last_v() -> None:
    # the kernel takes the ROM version after the LAST 'V': a model field may hold a V too
    identity = wacom4.parse_model_reply("~#CT-0045V02,V1.3-5,")
    assert (identity.code, identity.version) == ("CT", (1, 3))


def test_calcomp_stop_and_stream_commands() -> None:
    enc = make_encoder("calcomp")
    commands, rest = enc.split_commands(b"\x1b%JR1000,0\r\x1b%H\r")
    assert (commands, rest) == ([b"JR1000,0", b"H"], b"")
    for command in commands:
        enc.answer(command)
    assert not enc.streaming  # ESC%H: the stream stops
    enc.answer(b"IR")
    assert enc.streaming  # ESC%IR: it streams again
