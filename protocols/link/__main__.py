"""``python -m camlab88.protocols.link dump|stream|echo ...``."""

from __future__ import annotations

from camlab88.protocols.link.cli import main

raise SystemExit(main())
