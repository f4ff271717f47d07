"""The release-shaped build: a wheel holding camlab88/ only, installed (not editable) into a
fresh venv beside a project whose own apps/, base/, emulator/, protocols/, roms/ come first.

One venv for the module (building and installing take ~1 min; pip's cache makes the
dependencies quick). The user's side is run as a user would: the installed console script
and ``python -m pytest`` from the decoy project's directory.
"""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import textwrap
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
OURS = ("apps", "base", "emulator", "protocols", "roms")
DECOY_TEST = '''
import protocols  # the decoy project's own package
import base


def test_the_decoys_are_the_projects_own():
    assert protocols.MINE and base.MINE


def test_sigma_fixture(sigma, assert_no_protocol_errors):
    sigma.machine.host.write(b"\\r+-*/GI200200GJ400200400300BH")
    sigma.run()
    assert_no_protocol_errors(sigma)
    assert sigma.screen[511 - 200, 300].any()


def test_rainbow_fixture(rainbow):
    assert rainbow.client is not None


def test_sigma_pty_fixture(sigma_pty):
    with open(sigma_pty.path, "wb", buffering=0) as port:
        port.write(b"\\r+-*/GI200200GJ400200400300BH")
    sigma_pty.wait_idle()
    assert sigma_pty.screen()[511 - 200, 300].any()
'''

# one worker builds and installs once (two builds of one tree at a time share its build/)
pytestmark = [pytest.mark.slow, pytest.mark.xdist_group("packaging")]


def _run(cmd: list[str], cwd: Path, env: dict[str, str] | None = None,
         timeout: float = 600) -> subprocess.CompletedProcess[str]:
    done = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=timeout, check=False)
    assert done.returncode == 0, f"{cmd}\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


def _user_env(decoy: Path, library_cache: Path | None = None) -> dict[str, str]:
    """A user's environment: the decoy project first on the path, no display, no test-run
    numba cache. The ``camlab88`` command caches kernels under ``$XDG_CACHE_HOME`` (set to the
    decoy's own); a process using the library caches where numba's settings say, so those
    runs set ``NUMBA_CACHE_DIR`` as docs/api.md tells library users to."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CACHE_DIR", "PYTHONPATH", "CAMLAB88_NUMBA_RUN")
           and not k.startswith("PYTEST_")}
    env.update(PYTHONPATH=str(decoy), SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               XDG_CACHE_HOME=str(decoy / ".cache"))
    if library_cache is not None:
        env["NUMBA_CACHE_DIR"] = str(library_cache)
    env.pop("DISPLAY", None)
    return env


def _site_packages(venv: Path) -> Path:
    python = venv / "bin" / "python"
    out = _run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
               venv)
    return Path(out.stdout.strip())


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``python -m build``: an sdist and a wheel built from it, as a release is made."""
    out = tmp_path_factory.mktemp("dist")
    _run([sys.executable, "-m", "build", "--outdir", str(out), str(ROOT)], ROOT)
    assert len(list(out.glob("camlab88-*.tar.gz"))) == 1
    (found,) = out.glob("camlab88-*.whl")
    return found


@pytest.fixture(scope="module")
def venv(wheel: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    where = tmp_path_factory.mktemp("venv") / "v"
    _run([sys.executable, "-m", "venv", str(where)], where.parent)
    _run([str(where / "bin" / "pip"), "install", "-q", str(wheel), "pytest"], where.parent)
    return where


@pytest.fixture(scope="module")
def decoy(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A user's project whose packages have our old top-level names."""
    project = tmp_path_factory.mktemp("decoy")
    for name in OURS:
        (project / name).mkdir()
        (project / name / "__init__.py").write_text("MINE = True\n")
    (project / "test_host.py").write_text(DECOY_TEST)
    return project


def test_the_wheel_holds_camlab88_and_its_dist_info_only(wheel: Path) -> None:
    with zipfile.ZipFile(wheel) as z:
        tops = {name.split("/")[0] for name in z.namelist()}
        names = set(z.namelist())
    assert tops == {"camlab88", wheel.name.split("-py3")[0] + ".dist-info"}, tops
    # the mapped folders are inside, with their data files
    for module in ("camlab88/emulator/window.py", "camlab88/apps/ca/library/life.rules",
                   "camlab88/protocols/sigma/__init__.py", "camlab88/roms/__init__.py",
                   "camlab88/base/atomicfile.py", "camlab88/commands/ca/run.py"):
        assert module in names, module


def test_the_public_api_and_cli_work_beside_a_decoy_project(venv: Path, decoy: Path) -> None:
    env = _user_env(decoy, decoy / "numba")
    code = ("import protocols, camlab88; from camlab88 import Sigma, Rainbow; "
            "import camlab88.protocols.rainbow; assert protocols.MINE; "
            "print(Sigma.__module__, Rainbow.__module__)")
    out = _run([str(venv / "bin" / "python"), "-c", code], decoy, env)
    assert out.stdout.split() == ["camlab88.bench.sigma", "camlab88.bench.rainbow"]
    helped = _run([str(venv / "bin" / "camlab88"), "--help"], decoy, env)
    assert "usage: camlab88" in helped.stdout


def test_the_fixtures_work_in_the_decoy_projects_tests(venv: Path, decoy: Path) -> None:
    env = _user_env(decoy, decoy / "numba")
    done = _run([str(venv / "bin" / "python"), "-m", "pytest", "-q", "-p", "no:cacheprovider",
                 "test_host.py"], decoy, env)
    assert "4 passed" in done.stdout, done.stdout


def test_the_demo_runs_from_the_wheel(venv: Path, decoy: Path, tmp_path: Path) -> None:
    env = _user_env(decoy)
    done = _run([str(venv / "bin" / "camlab88"), "demo", "--only", "sigma", "--headless",
                 "--out", str(tmp_path / "demo")], tmp_path, env)
    assert list((tmp_path / "demo").rglob("*.png")), done.stderr
    # the command cached its compiled kernels per user, not inside site-packages
    assert list((decoy / ".cache" / "camlab88" / "numba").rglob("*.nbi")), done.stderr


def test_a_distribution_with_our_old_names_changes_nothing_of_ours(
        venv: Path, decoy: Path, tmp_path: Path) -> None:
    """A second distribution shipping top-level base/ and protocols/ (a wheel made here by
    hand: a wheel is a zip with its RECORD) installs beside us; pip check stays clean and
    uninstalling it leaves our package whole."""
    wheel = tmp_path / "squatter-1.0-py3-none-any.whl"
    files = {"base/__init__.py": "SQUAT = 1\n", "protocols/__init__.py": "SQUAT = 1\n",
             "squatter-1.0.dist-info/METADATA":
                 "Metadata-Version: 2.1\nName: squatter\nVersion: 1.0\n",
             "squatter-1.0.dist-info/WHEEL":
                 "Wheel-Version: 1.0\nGenerator: hand\nRoot-Is-Purelib: true\nTag: py3-none-any\n"}
    record = "".join(f"{name},,\n" for name in files) + "squatter-1.0.dist-info/RECORD,,\n"
    with zipfile.ZipFile(wheel, "w") as z:
        for name, text in {**files, "squatter-1.0.dist-info/RECORD": record}.items():
            z.writestr(name, text)
    pip = str(venv / "bin" / "pip")
    env = _user_env(decoy, decoy / "numba")
    env.pop("PYTHONPATH")
    _run([pip, "install", "-q", "--no-deps", str(wheel)], tmp_path, env)
    try:
        _run([pip, "check"], tmp_path, env)
        code = "from camlab88 import Sigma; s = Sigma(); s.run(); print('ok')"
        assert _run([str(venv / "bin" / "python"), "-c", code], tmp_path, env).stdout == "ok\n"
    finally:
        _run([pip, "uninstall", "-y", "-q", "squatter"], tmp_path, env)
    code = "import camlab88.base.atomicfile, camlab88.protocols.sigma; print('whole')"
    assert _run([str(venv / "bin" / "python"), "-c", code], tmp_path, env).stdout == "whole\n"


def test_uninstall_leaves_nothing_of_ours(venv: Path, decoy: Path, tmp_path: Path) -> None:
    """Runs last in this module (pytest keeps file order): after the demo and the fixtures
    have compiled and cached kernels, pip uninstall leaves no camlab88 file behind."""
    site = _site_packages(venv)
    assert (site / "camlab88").is_dir()
    _run([str(venv / "bin" / "pip"), "uninstall", "-y", "-q", "camlab88"], tmp_path)
    left = [str(f.relative_to(site)) for p in site.iterdir()
            if p.name.lower().startswith("camlab88") for f in [p, *p.rglob("*")]]
    assert left == [], left[:20]
    assert not (venv / "bin" / "camlab88").exists()


def test_this_tree_is_not_importable_under_a_second_name() -> None:
    """From the repository's top (on sys.path as ``python -m`` puts it), the design's folders
    refuse their bare names: one name for every module."""
    for name in OURS:
        done = subprocess.run([sys.executable, "-c", f"import {name}"], cwd=ROOT,
                              capture_output=True, text=True, timeout=60, check=False)
        assert done.returncode == 1
        assert f"import camlab88.{name}, not {name}" in done.stderr
    assert sysconfig.get_paths()["purelib"]  # (the venv the suite runs in is a real one)


def test_every_command_module_is_in_the_cli_layer() -> None:
    """The import contract's top layer names every module directly under camlab88 that is
    not one of the design's folders, so a new one cannot slip past the layers."""
    text = (ROOT / "pyproject.toml").read_text()
    layer = text.split('"areas : ', 1)[1].split('",', 1)[0]
    named = {"areas", *(n.strip() for n in layer.split(":"))}
    here = {p.stem for p in (ROOT / "camlab88").iterdir()
            if not p.name.startswith("__") and p.name not in OURS
            and (p.suffix == ".py" or (p / "__init__.py").exists())}
    assert here == named, textwrap.shorten(f"missing {here - named}, extra {named - here}", 200)
