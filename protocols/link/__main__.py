"""``python -m protocols.link dump|stream|echo ...``."""

from __future__ import annotations

from protocols.link.cli import main

raise SystemExit(main())
