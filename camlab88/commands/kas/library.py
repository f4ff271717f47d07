"""``camlab88 kas library``: list (or add to) the libraries."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import fail

DESCRIPTION = """\
Lists the user library ($CAMLAB88_KAS_LIBRARY, default ~/.local/share/camlab88/kas) and the \
shipped one. --save FILE NAME checks FILE and copies it into the user library; library names \
can then be given wherever a file is asked for. An entry of that NAME is replaced only with \
--force."""


HELP = "list (or add to) the libraries of keyframes, paths and timings"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--save", nargs=2, metavar=("FILE", "NAME"))
    p.add_argument("--force", action="store_true",
                   help="with --save: replace an existing entry of that NAME")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import library

    if args.save:
        return _save(*args.save, force=args.force)
    print(f"user library: {library.user_dir()}")
    for name, kind, where in library.entries():
        print(f"{name:28} {kind:9} {where}")
    return 0


def _save(src: str, name: str, force: bool = False) -> int:
    """``--save FILE NAME``: FILE checked, then copied into the user library as NAME (an
    existing NAME is kept unless ``force``)."""
    from camlab88.apps.kas import library
    from camlab88.apps.kas.program.file_kind import kind_of
    from camlab88.base.atomicfile import write_atomic

    try:
        if not Path(src).is_file():
            raise ValueError(f"{src} does not exist: make it first (e.g. 'camlab88 kas "
                             f"path A B --out {src}'), then save it into the library")
        text = Path(src).read_text(encoding="utf-8")
        kind = kind_of(text, src)
        dest = library.user_file(name)
        if dest.exists() and not force:
            raise ValueError(f"{name} is already in your library ({dest}); --force replaces "
                             "it, or choose another NAME")
        write_atomic(dest, text.encode("utf-8"))
    except (OSError, ValueError, UnicodeDecodeError) as exc:
        return fail("camlab88 kas library", exc)
    print(f"kas library: {kind} {src} saved as {dest}")
    return 0
