"""Every test gets its own empty KAS user library (never the real ~/.local/share one)."""

from __future__ import annotations

import pytest


@pytest.fixture(autouse=True)
def _user_library(tmp_path_factory, monkeypatch) -> None:
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(tmp_path_factory.mktemp("kaslib")))
