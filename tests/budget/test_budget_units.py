"""The budget's own rules (camlab88.base.budget): sizes as people write them, the default,
a bad setting named, the refusal's words."""

from __future__ import annotations

import pytest

from camlab88.base import budget


@pytest.mark.parametrize(("text", "size"), [
    ("1500M", 1500 << 20), ("4G", 4 << 30), ("2.5G", 5 << 29), ("1g", 1 << 30),
    ("64MiB", 64 << 20), ("2048K", 2 << 20), (str(3 << 20), 3 << 20), (" 1T ", 1 << 40),
])
def test_sizes(text: str, size: int) -> None:
    assert budget.parse_size(text) == size


@pytest.mark.parametrize("text", ["", "lots", "-1G", "1e9", "4 G B", "1" * 16, "512K"])
def test_bad_sizes_are_refused_in_words(text: str) -> None:
    with pytest.raises(ValueError, match="memory"):
        budget.parse_size(text)


def test_the_default_and_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(budget.ENV, raising=False)
    assert budget.limit() == budget.DEFAULT == 1 << 30
    monkeypatch.setenv(budget.ENV, "3G")
    assert budget.limit() == 3 << 30
    monkeypatch.setenv(budget.ENV, "plenty")
    with pytest.raises(budget.OverBudget, match="CAMLAB88_BUDGET='plenty'"):
        budget.limit()


def test_the_refusal_names_input_need_and_option(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(budget.ENV, "1G")
    budget.check("x.mc", 1 << 30, "its grid")  # at the limit: allowed
    with pytest.raises(budget.OverBudget) as err:
        budget.check("x.mc", 5 << 30, "its grid")
    assert str(err.value) == ("x.mc: its grid would need 5.0 GB; the memory budget is 1.0 GB "
                              "(raise it with camlab88 --budget SIZE or CAMLAB88_BUDGET=SIZE)")
