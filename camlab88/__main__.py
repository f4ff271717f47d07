from camlab88.cli import entry

raise SystemExit(entry())
