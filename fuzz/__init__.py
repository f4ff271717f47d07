"""Fuzzing camlab88's decoders and parsers: targets, a seed corpus per format, and runners
(``python fuzz/run.py --seconds N``; see docs/reliability.md)."""
