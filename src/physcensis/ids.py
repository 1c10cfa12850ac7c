"""Object identifiers: they become file names and MuJoCo body names, so keep them plain."""

from __future__ import annotations

import re

ID_PATTERN = re.compile(r"[A-Za-z0-9_-]{1,64}")
ID_RULE = "1-64 characters, each a letter, digit, '_' or '-'"
ROOT_ID = "root"
GROUP_PREFIX = "group_"
# Names every exported scene already uses for its own parts (the support, the floor, root nodes); case-insensitive
# because some exports (USD prims, files on case-insensitive disks) do not tell case apart.
RESERVED_IDS = (ROOT_ID, "support", "ground", "world", "scene")


def is_valid_id(value: str) -> bool:
    return ID_PATTERN.fullmatch(value) is not None


def is_reserved_id(value: str) -> bool:
    return value.lower() in RESERVED_IDS


def copy_member_id(member_id: str, group_id: str) -> str:
    """Id of `member_id`'s duplicate in the copied group `group_id`."""
    return f"{member_id}-{group_id}"
