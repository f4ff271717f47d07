"""How a film command (``snooker film``, ``ca film``) starts and ends: its input files looked
for before any work, and one line for each way a long render can stop — interrupted (the
frames written stay and the same command resumes), a camera script with errors, a refusal."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable
from pathlib import Path

from camlab88.runopts import fail


def run_film(command: str, inputs: Iterable[str | Path | None], film: Callable[[], int],
             refusals: tuple[type[Exception], ...]) -> int:
    """``film()`` once every given input exists (else ``FILE: no such file``, not a raw
    [Errno 2]); an interrupt is reported in one line and raised again (cli.main gives the
    exit status, 130 or 143); ``refusals`` become one line and exit 2."""
    from camlab88.apps.snooker.camera.errors import CclErrors

    missing = [p for p in inputs if p is not None and not Path(p).exists()]
    if missing:
        return fail(command, f"{missing[0]}: no such file")
    try:
        return film()
    except KeyboardInterrupt:
        print(f"{command}: interrupted; the frames written so far stay, and the same "
              "command resumes from them", file=sys.stderr)
        raise
    except CclErrors as exc:
        print(exc, file=sys.stderr)
        return fail(command, "the camera script has errors; nothing rendered")
    except OSError as exc:  # the inputs were found and the outputs checked: a write fault
        # during the render is the work failing (docs/exit_status.md: status 1)
        if not isinstance(exc, refusals):
            raise
        return fail(command, exc, 2 if isinstance(exc, FileNotFoundError) else 1)
    except refusals as exc:
        return fail(command, exc)
