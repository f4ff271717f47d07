"""A mistake on the command line gets one line — the message and where the usage is — not a
usage block; an option no command has is named as unknown (with its nearest), even when a
required option is missing too (the newcomer's `--input` was reported as "--in is required")."""

from __future__ import annotations

import pytest

from camlab88.cli import main

CASES = [
    (["sigma", "render", "--input", "x.sig", "--out", "y.png"],
     "camlab88 sigma render: unknown option --input; did you mean '--in'?"),
    (["sigma", "render", "--in", "x.sig", "--out", "y.png", "--bogus", "3"],
     "camlab88 sigma render: unknown option --bogus"),
    (["sigma", "render", "--in", "x.sig", "--out", "y.png", "--speed", "0"],
     "camlab88 sigma render: argument --speed: must be from 0.1 to 1000"),
    (["ca", "program", "--frames", "10"], "use --stop-after 10"),
    (["sigma", "render", "--in", "x.sig", "--out", "a.png", "--video", "out.avi"],
     "argument --video: makes .mp4 or .gif"),
    (["snooker", "film", "--titles", "X", "--out", "t.gif", "--size", "384"],
     "argument --size: expected WxH"),
    (["replay", "x.session", "--seek", "-1"], "argument --seek: must be 0 or more"),
    (["ca", "run", "--generations", "5"],
     "camlab88 ca run: the following arguments are required: --rules, --pattern"),
    (["snoker"], "did you mean 'snooker'?"),
]


@pytest.mark.parametrize("argv, says", CASES)
def test_a_parse_error_is_one_line_naming_the_help(argv: list[str], says: str,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as ended:
        main(argv)
    assert ended.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert says in err
    command = "camlab88 " + " ".join(w for w in argv[:2] if not w.startswith("-")
                                     and w not in ("snoker", "x.session"))
    assert err.rstrip().endswith(f"(see {command.strip()} --help)"), err
    assert "usage:" not in err


def test_an_abbreviation_argparse_accepts_is_not_unknown(capsys: pytest.CaptureFixture[str]
                                                         ) -> None:
    with pytest.raises(SystemExit):
        main(["ca", "run", "--generation", "5"])  # --generations, abbreviated
    assert "unknown option" not in capsys.readouterr().err
