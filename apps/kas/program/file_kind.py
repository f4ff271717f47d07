"""What kind of KAS file this is (its first line, ``KAS <kind> <version>``), checked by
parsing it whole: for saving a file into the user library."""

from __future__ import annotations

from camlab88.apps.kas import files

KINDS = {"keyframe": files.parse_keyframe, "sequence": files.parse_sequence,
         "path": files.parse_path, "timing": files.parse_timing}


def kind_of(text: str, name: str) -> str:
    """``keyframe``, ``sequence``, ``path`` or ``timing``; a file that is none of them, or
    a bad one, raises KasFileError naming the file and line."""
    first = text.split("\n", 1)[0].split()
    kind = first[1] if len(first) == 3 and first[0] == "KAS" else ""
    if kind not in KINDS:
        raise files.KasFileError(name, 1, "not a KAS keyframe, sequence, path or timing file "
                                 "(its first line should be 'KAS <kind> <version>')")
    KINDS[kind](text, name)  # refuse a bad file before it enters the library
    return kind
