"""SOURCE strings: parse them, and open the tablet they name.

Forms: ``hid:VID:PID`` (hex), ``serial:PORT?protocol=wacom4&baud=9600``, any pyserial URL with
``protocol=`` (``loop://?protocol=calcomp``, ``socket://127.0.0.1:7000?protocol=summa-mm``),
and ``emulated:PROTOCOL`` (the emulated tablet, opened by the command layer, which owns the
emulator).  Options other than ``protocol``/``baud``/``init`` go to the protocol's parser.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from urllib.parse import parse_qsl, urlencode

from camlab88.protocols.tablets.events import TabletEvent, TabletModel
from camlab88.protocols.tablets.registry import PROTOCOL_NAMES, known_options, resolve

OUR_KEYS = ("protocol", "baud", "init")


class SourceError(ValueError):
    """A SOURCE string that cannot be used (message says which part and why)."""


class SourceLost(ConnectionError):
    """The device went away (unplugged, stream broken); the caller may reopen later."""


@dataclass(frozen=True)
class SourceSpec:
    kind: str  # "hid", "serial", "url", "emulated"
    target: str  # VID:PID, port path, URL without our options, or protocol name
    protocol: str | None = None
    options: dict[str, str] = field(default_factory=dict)
    baud: int | None = None
    init: bool = True
    text: str = ""

    @property
    def device_key(self) -> str:
        """Stable name used to store per-device calibration."""
        if self.kind == "hid":
            return f"hid:{self.target}"
        return f"{self.kind}:{self.target}?protocol={self.protocol}"

    @property
    def vid_pid(self) -> tuple[int, int]:
        vid, pid = self.target.split(":")
        return int(vid, 16), int(pid, 16)


def _split_query(text: str) -> tuple[str, dict[str, str]]:
    if "?" not in text:
        return text, {}
    base, query = text.split("?", 1)
    return base, dict(parse_qsl(query, keep_blank_values=True))


def _protocol(name: str | None, where: str) -> str:
    if not name:
        raise SourceError(f"{where}: needs ?protocol= one of {', '.join(PROTOCOL_NAMES)}")
    try:
        resolve(name)
    except ValueError as exc:
        raise SourceError(f"{where}: {exc}") from None
    return name


def parse_source(text: str) -> SourceSpec:
    text = text.strip()
    if not text:
        raise SourceError("empty SOURCE")
    if text.startswith("hid:"):
        body, options = _split_query(text[4:])
        match = re.fullmatch(r"(?:0x)?([0-9a-fA-F]{1,4}):(?:0x)?([0-9a-fA-F]{1,4})", body)
        if match is None:
            raise SourceError(f"{text!r}: HID sources are hid:VID:PID in hex, e.g. hid:056a:0010")
        target = f"{int(match.group(1), 16):04x}:{int(match.group(2), 16):04x}"
        return SourceSpec("hid", target, None, options, text=text)
    if text.startswith("emulated:"):
        body, options = _split_query(text[len("emulated:"):])
        protocol = _protocol(body or "summa-mm", text)
        return SourceSpec("emulated", protocol, protocol, options, text=text)
    if text.startswith("serial:"):
        kind, rest = "serial", text[len("serial:"):]
    elif "://" in text:
        kind, rest = "url", text
    elif text.startswith("/") or re.match(r"COM\d+", text):
        kind, rest = "serial", text
    else:
        raise SourceError(
            f"{text!r}: not a SOURCE (use hid:VID:PID, serial:PORT?protocol=P, "
            "a pyserial URL with ?protocol=P, or emulated:P)"
        )
    base, options = _split_query(rest)
    if not base:
        raise SourceError(f"{text!r}: no port given")
    protocol = _protocol(options.pop("protocol", None), text)
    baud = None
    if "baud" in options:
        try:
            baud = int(options.pop("baud"))
        except ValueError:
            raise SourceError(f"{text!r}: baud must be a number") from None
    init = options.pop("init", "1") not in ("0", "no", "false", "off")
    # Options the protocol does not know stay in the URL for pyserial (e.g. logging=debug).
    known = known_options(protocol)
    ours = {k: v for k, v in options.items() if k in known}
    theirs = {k: v for k, v in options.items() if k not in known}
    if kind == "serial" and theirs:
        raise SourceError(f"{text!r}: unknown option(s) {', '.join(sorted(theirs))}")
    target = base + ("?" + urlencode(theirs) if theirs else "")
    return SourceSpec(kind, target, protocol, ours, baud, init, text)


class TabletSource:
    """What the monitor, calibration and input layer read from."""

    name: str = ""
    model: TabletModel

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        raise NotImplementedError

    def close(self) -> None:  # pragma: no cover - trivial default
        pass

    def __enter__(self) -> TabletSource:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def open_source(spec: SourceSpec | str, on_raw=None) -> TabletSource:
    """Open a hid/serial/url source.  ``emulated:`` sources are opened by the command layer
    (it starts the emulated tablet, then opens its pty as ``serial:``)."""
    if isinstance(spec, str):
        spec = parse_source(spec)
    if spec.kind == "hid":
        from camlab88.protocols.tablets.hid_source import HidSource

        return HidSource(spec, on_raw=on_raw)
    if spec.kind in ("serial", "url"):
        from camlab88.protocols.tablets.serial_source import SerialSource

        return SerialSource(spec, on_raw=on_raw)
    raise SourceError(f"{spec.text!r}: emulated sources are started by `camlab88 tablet ...`")
