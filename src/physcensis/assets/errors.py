"""Errors of the asset layer."""

from __future__ import annotations

from physcensis.errors import PhyscensisError


class AssetError(PhyscensisError):
    """An asset that cannot be built, loaded, found or ingested; the message names the culprit."""
