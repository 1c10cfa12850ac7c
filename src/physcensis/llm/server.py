"""What a chat server says about itself, asked cheaply: whether it is local, and the context window it serves.

The context is probed once per run: llama.cpp server's `/props` (`n_ctx`), vLLM's `/v1/models` (`max_model_len`)
and Ollama's `/api/show` (`num_ctx`), each with a short timeout, no redirects and a small size cap; whatever fails
is ignored.
"""

from __future__ import annotations

import ipaddress
import json
import re
import threading
import time
import urllib.error
import urllib.request
from typing import Any
from urllib.parse import urlsplit

PROBE_TIMEOUT_S = 1.5  # per probe request
PROBE_BUDGET_S = 4.0  # all probes together
MAX_PROBE_BYTES = 1024 * 1024


def is_local_server(base_url: str | None) -> bool:
    """Whether the server runs on this machine or the local network: localhost, loopback, private or link-local
    addresses, and *.local names."""
    try:
        host = (urlsplit(base_url or "").hostname or "").rstrip(".").lower()
    except ValueError:
        return False
    if not host:
        return False
    if host == "localhost" or host.endswith((".localhost", ".local")):
        return True
    try:
        address = ipaddress.ip_address(host)
    except ValueError:
        return False
    return address.is_loopback or address.is_private or address.is_link_local


def _positive_int(value: Any) -> int | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float) and 0 < value < 1e9:
        return int(value)
    return None


def _from_props(data: Any) -> int | None:
    """llama.cpp server's /props: `default_generation_settings.n_ctx` (or `n_ctx` at the top in older builds)."""
    if not isinstance(data, dict):
        return None
    settings = data.get("default_generation_settings")
    nested = settings.get("n_ctx") if isinstance(settings, dict) else None
    return _positive_int(nested) or _positive_int(data.get("n_ctx"))


def _from_models(data: Any, model: str) -> int | None:
    """vLLM's /v1/models: the served model's `max_model_len`."""
    rows = data.get("data") if isinstance(data, dict) else None
    if not isinstance(rows, list):
        return None
    lengths = {str(r.get("id")): _positive_int(r.get("max_model_len")) for r in rows if isinstance(r, dict)}
    return lengths.get(model) or next((n for n in lengths.values() if n), None)


def _from_ollama_show(data: Any) -> int | None:
    """Ollama's /api/show: `num_ctx` in the model's parameters (a text of "name value" lines)."""
    parameters = data.get("parameters") if isinstance(data, dict) else None
    if not isinstance(parameters, str):
        return None
    match = re.search(r"^\s*num_ctx\s+(\d+)\s*$", parameters, re.MULTILINE)
    return _positive_int(int(match.group(1))) if match else None


class _Prober:
    """GETs and POSTs to one server with short timeouts; `None` for anything but a small JSON answer."""

    def __init__(self, base_url: str, api_key: str | None, deadline: float) -> None:
        self.api = base_url.rstrip("/")
        self.root = self.api.removesuffix("/v1")
        self.deadline = deadline
        self.unreachable = False
        self.headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}

    def json(self, method: str, url: str, body: dict[str, Any] | None = None) -> Any:
        if self.unreachable or time.monotonic() > self.deadline or not url.startswith(("http://", "https://")):
            return None
        data = None if body is None else json.dumps(body).encode()
        headers = {**self.headers, **({"Content-Type": "application/json"} if data else {})}
        request = urllib.request.Request(url, data=data, headers=headers, method=method)
        try:
            with _OPENER.open(request, timeout=PROBE_TIMEOUT_S) as response:
                return json.loads(self._read(response))
        except urllib.error.HTTPError:
            return None  # the server answered: this endpoint is not there
        except (ValueError, RecursionError):  # not JSON, too large, too slow
            return None
        except OSError:  # no connection or no answer in time: the other probes would fare the same
            self.unreachable = True
            return None

    def _read(self, response: Any) -> bytes:
        data = bytearray()
        while chunk := response.read(64 * 1024):
            data += chunk
            if len(data) > MAX_PROBE_BYTES or time.monotonic() > self.deadline:
                raise ValueError("too large or too slow")
        return bytes(data)


class _NoRedirects(urllib.request.HTTPRedirectHandler):
    def redirect_request(self, *args: Any, **kwargs: Any) -> None:
        return None


_OPENER = urllib.request.build_opener(_NoRedirects)


def _probe(base_url: str, model: str, api_key: str | None) -> int | None:
    prober = _Prober(base_url, api_key, time.monotonic() + PROBE_BUDGET_S)
    found = _from_models(prober.json("GET", f"{prober.api}/models"), model) or _from_props(
        prober.json("GET", f"{prober.root}/props")
    )
    if found is None and isinstance(prober.json("GET", f"{prober.root}/api/version"), dict):  # an Ollama
        found = _from_ollama_show(prober.json("POST", f"{prober.root}/api/show", {"model": model}))
    return found


def probe_context_tokens(base_url: str, model: str, api_key: str | None = None) -> int | None:
    """The context window the server reports for `model`, or None (no such endpoint, no answer in time, ...).

    Runs on a daemon thread so that a server dripping its answer cannot hold the caller past `PROBE_BUDGET_S`.
    """
    result: list[int | None] = [None]

    def work() -> None:
        result[0] = _probe(base_url, model, api_key)

    thread = threading.Thread(target=work, name="physcensis-context-probe", daemon=True)
    thread.start()
    thread.join(PROBE_BUDGET_S + PROBE_TIMEOUT_S)
    return None if thread.is_alive() else result[0]
