"""A program part whose declared state is a few of its own attributes, saved as they are.

``STATE_SCHEMA`` (a ``Record``) names them once; ``state_values`` reads them and
``check_state_values`` puts them back (emulator.harness.program_state declares the protocol).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar

from camlab88.base.plainstate import Record


class AttributeState:
    """``state_values``/``check_state_values`` for a part whose ``STATE_SCHEMA`` fields are
    attributes of the same names, needing no check beyond the schema's."""

    STATE_SCHEMA: ClassVar[Record]

    def state_values(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in self.STATE_SCHEMA.fields}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        def put() -> None:
            for name in self.STATE_SCHEMA.fields:
                setattr(self, name, values[name])
        return put
