"""The project's error types: every failure a user can cause is one of these."""

from __future__ import annotations

import re

# C0 and C1 control characters and Unicode's line and paragraph separators: a message quoting a file's text must not
# break the `error:` line or send the terminal an escape sequence.
_CONTROL = re.compile(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def one_line(text: str) -> str:
    """`text` with every control character written as its escape (a line break as `\\n`), so it prints as one
    plain line whatever a file put in it."""
    return _CONTROL.sub(lambda m: m.group().encode("unicode_escape").decode("ascii"), text)


class PhyscensisError(Exception):
    """Base class: a clear, one-line problem a user can act on. The message prints as one line even where it quotes
    a file's text (control characters are escaped)."""

    def __str__(self) -> str:
        return one_line(super().__str__())


class ProgramParseError(PhyscensisError):
    """Text that holds no recognisable predicate program."""


class SceneFormatError(PhyscensisError):
    """A scene file that is not a valid `physcensis.scene/1` document."""


class ExportError(PhyscensisError):
    """A scene that cannot be written in the asked format (unknown format, missing optional extra)."""


class UnreadablePromptError(PhyscensisError):
    """A prompt that names nothing the offline reading knows (no object, no diners, no kind of scene)."""


class AgentError(PhyscensisError):
    """The agent could not produce anything (e.g. the LLM server is unreachable after retries)."""


class ExportMismatchError(PhyscensisError):
    """A scene folder's export that does not belong to its scene.json, or that cannot be read safely (the message
    names the file and what is wrong)."""
