"""Coverage-guided fuzzing of one target with atheris (libFuzzer):
``python -m fuzz.atheris_target NAME [libFuzzer flags] SCRATCH_DIR SEED_DIR``.
New inputs go to the first directory (scratch), never into the repository's corpus."""

from __future__ import annotations

import sys

import atheris

from fuzz.targets import TARGETS


def main() -> None:
    target = TARGETS[sys.argv[1]]
    for seed in target.seeds()[:1]:
        target.check(seed)  # import everything the target uses, so it gets instrumented
    atheris.instrument_all()
    atheris.Setup([sys.argv[0], *sys.argv[2:]], target.check)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
