"""The golden helper writes only inside the test's golden directory: ``--camlab88-regen``
with a name that climbs out, an absolute name, or a symbolic link out of the directory is
refused, and nothing outside is written or replaced."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.bench.golden import compare_golden, golden_path

pytest_plugins = ["pytester"]
SCREEN = np.zeros((4, 6, 3), np.uint8)


@pytest.mark.parametrize("name", ["../escape", "/tmp/escape", "a/b", "..", ".", "", "c:x",
                                  "a\\b"])
def test_a_name_that_is_not_a_plain_file_name_is_refused(tmp_path: Path, name: str) -> None:
    golden = tmp_path / "golden"
    golden.mkdir()
    with pytest.raises(ValueError, match="camlab88_golden"):
        golden_path(golden, name)
    assert [p.name for p in tmp_path.iterdir()] == ["golden"]


def test_a_symlink_out_of_the_directory_is_refused_and_its_target_kept(tmp_path: Path) -> None:
    golden = tmp_path / "golden"
    golden.mkdir()
    outside = tmp_path / "precious.png"
    outside.write_bytes(b"not yours")
    (golden / "shot.png").symlink_to(outside)
    with pytest.raises(ValueError, match="leads out of the golden directory"):
        golden_path(golden, "shot")
    assert outside.read_bytes() == b"not yours"


def test_a_plain_name_is_written_inside(tmp_path: Path) -> None:
    golden = tmp_path / "golden"
    golden.mkdir()
    path = golden_path(golden, "shot")
    compare_golden(SCREEN, path, regen=True)
    compare_golden(SCREEN, path, regen=False)
    assert sorted(p.name for p in golden.iterdir()) == ["shot.png"]


def test_the_fixture_refuses_under_regen(pytester: pytest.Pytester, tmp_path: Path) -> None:
    """End to end through the plugin's fixture, as a user's own test suite runs it."""
    outside = tmp_path / "victim.png"
    outside.write_bytes(b"keep")
    pytester.mkdir("golden")
    (pytester.path / "golden" / "linked.png").symlink_to(outside)
    pytester.makepyfile(f"""
        import numpy as np
        import pytest

        SCREEN = np.zeros((2, 2, 3), np.uint8)

        @pytest.mark.parametrize("name", ["../up", {str(tmp_path / "abs")!r}, "linked"])
        def test_out(camlab88_golden, name):
            with pytest.raises(ValueError):
                camlab88_golden(SCREEN, name)

        def test_in(camlab88_golden):
            camlab88_golden(SCREEN, "fine")
    """)
    result = pytester.runpytest_subprocess("--camlab88-regen", "-p", "no:cacheprovider")
    result.assert_outcomes(passed=4)
    assert outside.read_bytes() == b"keep"
    assert not (pytester.path / "up.png").exists() and not (tmp_path / "abs.png").exists()
    assert (pytester.path / "golden" / "fine.png").is_file()
