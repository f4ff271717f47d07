"""The camlab88 pytest plugin is normally loaded through its pytest11 entry point (an
installed camlab88); an environment installed before the entry point existed still gets it."""

from __future__ import annotations

import pytest


def pytest_configure(config: pytest.Config) -> None:
    if not config.pluginmanager.has_plugin("camlab88") and \
            not config.pluginmanager.has_plugin("camlab88.bench.plugin"):
        config.pluginmanager.import_plugin("camlab88.bench.plugin")
