"""Object identifiers: they become file names and MuJoCo body names, so keep them plain."""

from __future__ import annotations

import difflib
import re
import unicodedata
from collections.abc import Container, Iterable

ID_PATTERN = re.compile(r"[A-Za-z0-9_-]{1,64}")
MAX_ID_CHARS = 64
ID_RULE = "1-64 characters, each a letter, digit, '_' or '-'"
FALLBACK_SLUG = "item"
ROOT_ID = "root"
GROUP_PREFIX = "group_"
# Names every exported scene already uses for its own parts (the support, the floor, root nodes); case-insensitive
# because some exports (USD prims, files on case-insensitive disks) do not tell case apart.
RESERVED_IDS = (ROOT_ID, "support", "ground", "world", "scene")


PIN_PREFIX = "asset:"  # an object description "asset:ID" (optionally followed by words) names its asset exactly


def pinned_id(description: str) -> str | None:
    """The asset id a description pins ("asset:rs_can", "asset:rs_can a soda can"; "" when the id is missing), or
    None when it pins nothing."""
    text = description.strip()
    if text[: len(PIN_PREFIX)].lower() != PIN_PREFIX:
        return None
    rest = text[len(PIN_PREFIX) :].strip()
    return rest.split(maxsplit=1)[0] if rest else ""


def is_valid_id(value: str) -> bool:
    return ID_PATTERN.fullmatch(value) is not None


def is_reserved_id(value: str) -> bool:
    return value.lower() in RESERVED_IDS


def copy_member_id(member_id: str, group_id: str) -> str:
    """Id of `member_id`'s duplicate in the copied group `group_id`."""
    return f"{member_id}-{group_id}"


def slug(text: str, max_chars: int = 20) -> str:
    """Plain lower-case ASCII words of any text joined by '_' ("Crème brûlée" -> "creme_brulee"), at most
    `max_chars` long; FALLBACK_SLUG when nothing usable is left (emoji, punctuation, an empty string)."""
    folded = unicodedata.normalize("NFKD", text[: 8 * max_chars + 64]).encode("ascii", "ignore").decode("ascii").lower()
    words = re.findall(r"[a-z0-9]+", folded)
    joined = "_".join(words)[: max(1, max_chars)].strip("_")
    return joined or FALLBACK_SLUG


def unique_id(parts: list[str], taken: Container[str]) -> str:
    """A valid id made of `parts` joined by '_' plus a counter ("apple_bowl_0_3"), truncated so it fits the id
    rule, never in `taken` and never reserved. Deterministic: the same parts and taken set give the same id."""
    safe = [re.sub(r"[^A-Za-z0-9_-]+", "_", part).strip("_") for part in parts]
    base = "_".join(p for p in safe if p) or FALLBACK_SLUG
    n = 0
    while True:
        counter = f"_{n}"
        candidate = base[: MAX_ID_CHARS - len(counter)].rstrip("_-") + counter
        if candidate not in taken and not is_reserved_id(candidate):
            return candidate
        n += 1


MAX_MATCHED_CHARS = (
    200  # a name longer than any real one gets no "did you mean": matching it costs its length in memory
)


def close_match(name: str, known: Iterable[str], cutoff: float = 0.6) -> str | None:
    """The known name closest to a misspelt one ("did you mean"), or None; none for names far longer than any real
    one (difflib indexes every character of the name: a megabyte-long id took 36 MB and half a second)."""
    if len(name) > MAX_MATCHED_CHARS:
        return None
    matches = difflib.get_close_matches(name, [k for k in known if len(k) <= MAX_MATCHED_CHARS], n=1, cutoff=cutoff)
    return matches[0] if matches else None
