"""Example predicate programs shipped with the package."""

from __future__ import annotations

from pathlib import Path

EXAMPLES_DIR = Path(__file__).parent


def example_path(name: str) -> Path:
    """Path of a bundled example program, e.g. `example_path("desk_basic.json")`."""
    path = EXAMPLES_DIR / name
    if not path.is_file():
        known = ", ".join(sorted(p.name for p in list_examples()))
        raise FileNotFoundError(f"no example named {name!r}; known: {known}")
    return path


def list_examples() -> list[Path]:
    return sorted(p for p in EXAMPLES_DIR.iterdir() if p.suffix in {".json", ".txt"})
