"""Benchmarks: `python -m physcensis.bench` (what `make bench` runs) writes JSON results."""
