"""Every command that renders snooker frames offers every render mode of the renderer, from
the one list (apps/snooker/render/modes.py), so no command is left a mode short."""

from __future__ import annotations

import argparse

import pytest

from camlab88.apps.snooker.render.modes import MODES, SIGMA_MODES
from camlab88.apps.snooker.render.sigma_host import SigmaHost
from camlab88.cli import build_parser


def _subparser(parser: argparse.ArgumentParser, name: str) -> argparse.ArgumentParser:
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return sub.choices[name]


@pytest.mark.parametrize("action", ["film", "render"])
def test_snooker_commands_offer_every_render_mode(action: str) -> None:
    command = _subparser(_subparser(build_parser(), "snooker"), action)
    mode = next(a for a in command._actions if "--mode" in a.option_strings)
    assert tuple(mode.choices) == MODES


def test_the_sigma_host_draws_every_sigma_mode_and_refuses_the_rest() -> None:
    assert "adapted" in SIGMA_MODES and set(MODES) - set(SIGMA_MODES) == {"truecolour"}
    with pytest.raises(ValueError, match="unknown Sigma mode"):
        SigmaHost(None, None, mode="truecolour")  # refused before scene or palette are used
