"""The project's error types: every failure a user can cause is one of these."""

from __future__ import annotations


class PhyscensisError(Exception):
    """Base class: a clear, one-line problem a user can act on."""


class ProgramParseError(PhyscensisError):
    """Text that holds no recognisable predicate program."""


class SceneFormatError(PhyscensisError):
    """A scene file that is not a valid `physcensis.scene/1` document."""


class ExportError(PhyscensisError):
    """A scene that cannot be written in the asked format (unknown format, missing optional extra)."""


class UnreadablePromptError(PhyscensisError):
    """A prompt that names nothing the offline reading knows (no object, no diners, no kind of scene)."""


class ExportMismatchError(PhyscensisError):
    """A scene folder's export that does not belong to its scene.json, or that cannot be read safely (the message
    names the file and what is wrong)."""
