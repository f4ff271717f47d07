"""``camlab88 kas library``: list (or add to) the libraries."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.runopts import fail


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = actions.add_parser("library", help="list (or add to) the libraries of keyframes, paths "
                        "and timings", description="Lists the user library ($CAMLAB88_KAS_"
                        "LIBRARY, default ~/.local/share/camlab88/kas) and the shipped one. "
                        "--save FILE NAME checks FILE and copies it into the user library; "
                        "library names can then be given wherever a file is asked for.")
    p.add_argument("--save", nargs=2, metavar=("FILE", "NAME"))
    p.set_defaults(handler=_library)


def _library(args: argparse.Namespace) -> int:
    from apps.kas import library

    if args.save:
        from apps.kas import files
        from protocols.atomicfile import write_atomic

        src, name = args.save
        loaders = {"keyframe": files.parse_keyframe, "sequence": files.parse_sequence,
                   "path": files.parse_path, "timing": files.parse_timing}
        try:
            if not Path(src).is_file():
                raise ValueError(f"{src} does not exist: make it first (e.g. 'camlab88 kas "
                                 f"path A B --out {src}'), then save it into the library")
            text = Path(src).read_text(encoding="utf-8")
            first = text.split("\n", 1)[0].split()
            kind = first[1] if len(first) == 3 and first[0] == "KAS" else ""
            if kind not in loaders:
                raise files.KasFileError(src, 1, "not a KAS keyframe, sequence, path or "
                                         "timing file")
            loaders[kind](text, src)  # refuse a bad file before it enters the library
            dest = library.user_file(name)
            write_atomic(dest, text.encode("utf-8"))
        except (OSError, ValueError, UnicodeDecodeError) as exc:
            return fail("camlab88 kas library", exc)
        print(f"kas library: {kind} {src} saved as {dest}")
        return 0
    print(f"user library: {library.user_dir()}")
    for name, kind, where in library.entries():
        print(f"{name:28} {kind:9} {where}")
    return 0
