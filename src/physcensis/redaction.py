"""Keep credentials out of everything the tool writes or prints.

Two kinds of secret reach the tool: an API key (from the environment) and the userinfo of a server URL
(`http://user:password@host/v1`). `Redactor` knows the literal secrets of one run and also removes any URL
userinfo and bearer token it sees, so a server reply that quotes a header or an error that repeats the URL is
safe to log.
"""

from __future__ import annotations

import base64
import re
from collections.abc import Iterable
from typing import Any
from urllib.parse import unquote, urlsplit, urlunsplit

REDACTED = "[redacted]"
MIN_SECRET_CHARS = 4  # shorter strings would redact ordinary words; no real key or password is that short

# Bounded repeats keep every pattern linear in the text's length (an LLM reply may be megabytes of one word).
_URL_USERINFO = re.compile(r"(?P<scheme>\b[A-Za-z][A-Za-z0-9+.-]{0,31}://)(?P<userinfo>[^/\s@]{1,1024})@")
_BEARER = re.compile(r"(?i)\b(bearer|basic)\s{1,16}([A-Za-z0-9._~+/=-]{8,4096})")
_AUTH_HEADER = re.compile(
    r"(?i)(\b(?:authorization|api-key|x-api-key)[\"']?\s{0,16}[:=]\s{0,16}[\"']?"
    r"(?:(?:bearer|basic)\s{1,16})?)([^\s\"',}]{1,4096})"
)


def _token_like(word: str) -> bool:
    """A credential rather than a word ("a basic rectangular table"): digits, symbols or inner capitals."""
    return any(c.isdigit() or c in "._~+/=-" for c in word) or any(c.isupper() for c in word[1:])


def url_secrets(url: str | None) -> list[str]:
    """The password and user name of `url`'s userinfo (raw and percent-decoded), and the Basic credentials an
    HTTP client sends for them, if it has any."""
    if not url:
        return []
    try:
        parts = urlsplit(url)
    except ValueError:
        return []
    found: list[str] = []
    for value in (parts.password, parts.username):
        if value:
            found += [value, unquote(value)]
    return found + basic_credentials(url)


def basic_credentials(url: str | None) -> list[str]:
    """The `user:password` of `url` in clear and as sent in a Basic authorization header (base64)."""
    try:
        parts = urlsplit(url or "")
        user, password = parts.username, parts.password
    except ValueError:
        return []
    if not password:
        return []
    found: list[str] = []
    for pair in {f"{user or ''}:{password}", f"{unquote(user or '')}:{unquote(password)}"}:
        found += [pair, base64.b64encode(pair.encode()).decode("ascii")]
    return found


def strip_userinfo(url: str | None) -> str | None:
    """`url` without its `user:password@` part (None stays None)."""
    if not url:
        return url
    try:
        parts = urlsplit(url)
    except ValueError:
        return _URL_USERINFO.sub(lambda m: m.group("scheme"), url)
    if "@" not in parts.netloc:
        return url
    return urlunsplit(parts._replace(netloc=parts.netloc.rsplit("@", 1)[1]))


class Redactor:
    """Removes the given secrets, any URL userinfo and any bearer token from text and JSON-like data."""

    def __init__(self, secrets: Iterable[str | None] = ()) -> None:
        unique = {s for s in secrets if s and len(s) >= MIN_SECRET_CHARS}
        self.secrets = sorted(unique, key=len, reverse=True)  # longest first: a key containing another

    @classmethod
    def for_server(cls, api_key: str | None, base_url: str | None) -> Redactor:
        return cls([api_key, *url_secrets(base_url)])

    def text(self, value: str) -> str:
        for secret in self.secrets:
            value = value.replace(secret, REDACTED)
        value = _URL_USERINFO.sub(lambda m: f"{m.group('scheme')}{REDACTED}@", value)
        value = _BEARER.sub(lambda m: f"{m.group(1)} {REDACTED}" if _token_like(m.group(2)) else m.group(0), value)
        return _AUTH_HEADER.sub(lambda m: f"{m.group(1)}{REDACTED}", value)

    def data(self, value: Any) -> Any:
        """A copy of a JSON-like value with every string (keys included) redacted."""
        if isinstance(value, str):
            return self.text(value)
        if isinstance(value, dict):
            return {self.data(k) if isinstance(k, str) else k: self.data(v) for k, v in value.items()}
        if isinstance(value, list | tuple):
            return [self.data(v) for v in value]
        return value
