"""What every fuzz target shares: the profile's budget, the outcome check, the time and allocation bounds.

A reader given any input either returns or raises one of the project's own errors (a `PhyscensisError`, or an
`OSError`: the command line turns both into one `error:` line and exit code 2) with a one-line message. Anything
else is a finding:
* another exception type (KeyError, RecursionError, UnicodeDecodeError, a pydantic ValidationError, ...);
* a message of several lines, with control characters, or an empty one;
* a peak of memory over `4 x the input's size on disk + 64 MB` (the issue's bound on peak memory; `peak_memory`);
* a call taking more CPU time than TIME_BASE_S + TIME_PER_MB_S per megabyte of input (work out of proportion to the
  input), or one that hangs (`hang_guard` interrupts it after a while of wall time, so the example is reported and
  shrunk like any other).

FUZZ_PROFILE chooses the profile (see conftest.py): "ci" (the default, as `make test` runs it) or "long" (`make fuzz`).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import hashlib
import json
import os
import shutil
import signal
import stat
import time
import tracemalloc
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import pytest
from hypothesis import settings

import tests.fuzz.conftest  # noqa: F401 - registers the profiles (pytest has imported it already)
from physcensis.errors import PhyscensisError

T = TypeVar("T")
PROFILE_ENV = "FUZZ_PROFILE"
ALLOWED = (PhyscensisError, OSError)  # what the CLI reports as one error line and exit code 2
MEMORY_SLACK = 64 * 2**20
MEMORY_FACTOR = 4
TIME_BASE_S = 2.0  # a reader call on a small input takes milliseconds (MuJoCo's compile: tens of them)
TIME_PER_MB_S = 10.0  # and per megabyte of input (100 KB a second): linear work passes, work repeated over it does not
FINDINGS_DIR = Path(__file__).resolve().parents[2] / ".hypothesis" / "fuzz-findings"  # each test's last failing input
KEEP_MAX_BYTES = 256 * 2**20


@dataclass(frozen=True)
class Budget:
    """The limits of one profile: Hypothesis's settings, the whole test's timeout (pytest-timeout's thread method:
    the backstop for a hang in C code that holds the GIL; it dumps every stack and ends the run) and the least time
    after which `hang_guard` interrupts a call."""

    settings: settings
    test_timeout_s: int
    hang_s: float


def budget(name: str) -> Budget:
    if name not in ("ci", "long"):
        raise pytest.UsageError(f"{PROFILE_ENV}={name!r}: use ci or long")
    if name == "long":
        return Budget(settings.get_profile("fuzz-long"), test_timeout_s=4 * 3600, hang_s=60)
    return Budget(settings.get_profile("fuzz-ci"), test_timeout_s=180, hang_s=20)


PROFILE = os.environ.get(PROFILE_ENV, "ci")
BUDGET = budget(PROFILE)
FUZZ = BUDGET.settings  # decorate each @given test with it
TIMEOUT = pytest.mark.timeout(BUDGET.test_timeout_s, method="thread")


def size_on_disk(paths: Iterable[Path]) -> int:
    """Bytes of the regular files under `paths` as stored (a sparse file counts its written blocks only; links and
    special files count for nothing)."""
    total = 0
    for path in paths:
        for entry in [path, *path.rglob("*")] if path.is_dir() and not path.is_symlink() else [path]:
            try:
                info = entry.lstat()
            except OSError:
                continue
            if stat.S_ISREG(info.st_mode):
                total += min(info.st_size, info.st_blocks * 512)
    return total


def memory_bound(input_bytes: int) -> int:
    return MEMORY_FACTOR * input_bytes + MEMORY_SLACK


def time_bound(input_bytes: int) -> float:
    return TIME_BASE_S + TIME_PER_MB_S * input_bytes / 1e6


class Hang(Exception):
    """A call that ran past its hang guard (a blocked read, a loop that does not end)."""


@contextmanager
def hang_guard(seconds: float) -> Iterator[None]:
    """Raise `Hang` in the call after `seconds` of wall time; a blocking system call is interrupted too. SIGALRM is
    ours: the tests' own timeout uses a thread."""

    def stop(signum: int, frame: object) -> None:
        raise Hang(f"still running after {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _rss_kb(field: str) -> int:
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    raise OSError(f"no {field} in /proc/self/status")


def _release_free_memory() -> None:
    """Give the memory malloc keeps after frees back to the system: the next allocations then show in the resident
    size instead of reusing pages already counted."""
    if _LIBC is not None:
        _LIBC.malloc_trim(0)


_LIBC = ctypes.CDLL(ctypes.util.find_library("c")) if ctypes.util.find_library("c") else None


@contextmanager
def peak_memory() -> Iterator[Callable[[], int]]:
    """Measure the peak memory of what runs inside, in bytes above what the process held before: resident memory
    (Linux's high-water mark, reset on entry: it counts numpy, zlib and MuJoCo too, at no cost), or where that cannot
    be reset, tracemalloc's traced peak (Python's allocators only, and several times slower)."""
    try:
        _release_free_memory()
        with open("/proc/self/clear_refs", "w") as clear:
            clear.write("5")  # resets VmHWM to the current resident size
        before = _rss_kb("VmRSS")
    except OSError:
        before = -1
    if before >= 0:
        yield lambda: 1024 * max(0, _rss_kb("VmHWM") - before)
        return
    tracemalloc.start()
    try:
        yield lambda: tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def read_safely(call: Callable[[], T], input_bytes: int, keep: Path | None = None) -> T | None:
    """`call()`'s result, or None when it raised an allowed error with a one-line message; any other exception
    propagates (Hypothesis reports and shrinks it). Its time and peak memory must stay within bounds. On a finding,
    the input `keep` (a file or folder) is copied where the report says (the last one kept is the shrunk one)."""
    try:
        return _bounded_call(call, input_bytes)
    except Exception as exc:
        if keep is not None:
            exc.add_note(f"the input is kept in {keep_input(keep)}")
        raise


def _bounded_call(call: Callable[[], T], input_bytes: int) -> T | None:
    result: T | None = None
    refusal: BaseException | None = None
    seconds = time_bound(input_bytes)
    with peak_memory() as peak:
        start = time.process_time()  # CPU time: other processes on the machine do not count
        try:
            with hang_guard(max(BUDGET.hang_s, 3 * seconds)):
                result = call()
        except ALLOWED as exc:
            refusal = exc
        elapsed = time.process_time() - start
        used = peak()
    limit = memory_bound(input_bytes)
    _record_measure(input_bytes, used, elapsed)
    assert used <= limit, f"used {used:,} bytes at peak, over {limit:,} (input of {input_bytes:,} bytes)"
    assert elapsed <= seconds, f"took {elapsed:.1f} s of CPU, over {seconds:.1f} s (input of {input_bytes:,} bytes)"
    if refusal is not None:
        check_message(refusal)
    return result


def _record_measure(input_bytes: int, peak_bytes: int, cpu_s: float) -> None:
    """With FUZZ_MEASURES set to a file, append one JSON line per call: the test, its input size, peak and CPU time
    (how the README's peak-memory figures are measured)."""
    target = os.environ.get("FUZZ_MEASURES")
    if target:
        test = os.environ.get("PYTEST_CURRENT_TEST", "").split(" ")[0]
        row = {"test": test, "input_bytes": input_bytes, "peak_bytes": peak_bytes, "cpu_s": round(cpu_s, 3)}
        with open(target, "a", encoding="utf-8") as out:
            out.write(json.dumps(row) + "\n")


def keep_input(path: Path) -> Path:
    """Copy a failing input to FINDINGS_DIR/<test>/ (replacing the test's last one): regular files up to
    KEEP_MAX_BYTES, folders and links as they are; FIFOs, devices and huge (sparse) files are left out."""
    test = os.environ.get("PYTEST_CURRENT_TEST", "outside-pytest").split(" ")[0]
    slot = FINDINGS_DIR / "".join(c if c.isalnum() or c in "-_." else "_" for c in test)
    shutil.rmtree(slot, ignore_errors=True)
    slot.mkdir(parents=True)
    if path.is_dir() and not path.is_symlink():
        shutil.copytree(path, slot / path.name, symlinks=True, ignore=_unkept)
    elif path.is_symlink() or not _unkept(str(path.parent), [path.name]):
        shutil.copy2(path, slot / path.name, follow_symlinks=False)
    return slot / path.name


def _unkept(folder: str, names: list[str]) -> set[str]:
    left_out = set()
    for name in names:
        info = os.lstat(os.path.join(folder, name))
        if not (stat.S_ISDIR(info.st_mode) or stat.S_ISLNK(info.st_mode) or stat.S_ISREG(info.st_mode)):
            left_out.add(name)
        elif stat.S_ISREG(info.st_mode) and info.st_size > KEEP_MAX_BYTES:
            left_out.add(name)
    return left_out


class Blob(bytes):
    """Bytes that Hypothesis shows by their size, hash and ends, not whole (an input can be megabytes long)."""

    def __repr__(self) -> str:
        digest = hashlib.sha256(self).hexdigest()[:12]
        return f"<{len(self):,} bytes, sha256 {digest}…: {bytes(self[:80])!r} … {bytes(self[-40:])!r}>"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:  # Hypothesis's printer, which knows bytes otherwise
        printer.text(repr(self))


def check_message(exc: BaseException) -> None:
    """A refusal is one line saying what is wrong, with no control character a file could have put there (a line
    break, a terminal escape)."""
    message = str(exc)
    assert message.strip(), f"{type(exc).__name__} with an empty message"
    assert "\n" not in message and "\r" not in message, f"{type(exc).__name__} on several lines: {message[:300]!r}"
    controls = sorted({c for c in message if ord(c) < 32 and c != "\t" or ord(c) == 127})
    assert not controls, f"{type(exc).__name__} with control characters {controls}: {message[:300]!r}"


def copy_folder(source: Path, target: Path, skip: Iterable[str] = ()) -> Path:
    """A copy of a seed folder to damage (links copied as links); the top-level entries in `skip` left out."""
    left_out = set(skip)
    shutil.copytree(source, target, symlinks=True, ignore=lambda d, names: left_out if d == str(source) else set())
    return target
