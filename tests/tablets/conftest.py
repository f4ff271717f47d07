from __future__ import annotations

import pytest

from tests.tablets.helpers import PtyPair


@pytest.fixture
def pty_pair():
    pair = PtyPair()
    yield pair
    pair.close()


@pytest.fixture(scope="module")
def shared_pty():
    """One pty for a module's hypothesis round trips (opening one per example is slow)."""
    pair = PtyPair()
    yield pair
    pair.close()
