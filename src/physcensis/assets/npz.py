"""Reading an untrusted `.npz` payload within bounds: what it declares is checked before anything is allocated.

`numpy.load` trusts a zip member's declared size and unpacks whatever it holds, so a file of a megabyte can unpack to
gigabytes (a compression bomb); and `zipfile` parses the whole central directory, however long, before a member can be
looked at. `read_npz` refuses, from the zip's end record, a directory longer than the members allowed need; then
unexpected or duplicated member names, encryption and compression methods other than stored and deflated; a total
declared size over the bound (absolute, and as a ratio to the payload's own size); .npy headers that are not numpy's
own (version, length, dtype: numbers only, no objects or structures); and a member whose declared size is not its
header plus shape x itemsize. Each array is then read into its own buffer, a chunk at a time, never beyond what it
declared (one more byte is asked for, to catch a member that unpacks past its declared size).
"""

from __future__ import annotations

import io
import re
import struct
import zipfile
import zlib
from dataclasses import dataclass
from math import prod
from typing import IO

import numpy as np
from numpy.lib import format as npy

from physcensis.assets.meshfile import first_line
from physcensis.errors import PhyscensisError
from physcensis.fileio import BoundError

# zip's end record: signature, disk numbers, entries (on this disk, in all), directory size and offset, comment length
_END_RECORD = struct.Struct("<4s4H2LH")
_END_SIGNATURE = b"PK\x05\x06"
_ZIP64_LOCATOR = b"PK\x06\x07"
_LOCATOR_BYTES = 20
DIRECTORY_ENTRY_BYTES = 256  # one member's directory record: 46 bytes, its name and any extra fields
MAX_HEADER_BYTES = 4096  # numpy writes 128 bytes for an array of up to 3 dimensions
_KINDS = "iuf"  # integers and floats; no booleans, complex, strings, objects or structures
_METHODS = (zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED)
_CHUNK = 1 << 20
# What zipfile and numpy raise on a damaged archive or header (zlib.error for a broken deflate stream).
_DAMAGE = (
    zipfile.BadZipFile,
    zipfile.LargeZipFile,
    zlib.error,
    struct.error,
    EOFError,
    OSError,
    ValueError,
    NotImplementedError,
)


class NpzError(PhyscensisError, ValueError):
    """A payload that is not an `.npz` file as numpy writes it; the message says what is wrong."""


@dataclass(frozen=True)
class NpzBounds:
    """What one payload may hold: which array names, how many, and how many bytes once unpacked.

    The unpacked total may reach `max_unpacked`, but never more than `max_ratio` times the payload's own size unless
    it stays under `small_unpacked` (small payloads compress their headers and zeros well; large ones cannot).
    """

    names: re.Pattern[str]
    max_members: int
    max_unpacked: int
    max_ratio: float
    small_unpacked: int

    def unpacked_limit(self, size: int) -> int:
        return min(self.max_unpacked, max(self.small_unpacked, int(self.max_ratio * size)))


@dataclass(frozen=True)
class _Member:
    info: zipfile.ZipInfo
    name: str
    header_bytes: int
    dtype: np.dtype
    shape: tuple[int, ...]
    fortran: bool

    @property
    def nbytes(self) -> int:
        return prod(self.shape) * self.dtype.itemsize


def read_npz(data: bytes, bounds: NpzBounds) -> dict[str, np.ndarray]:
    """The arrays of an `.npz` payload by name; `BoundError` for one over `bounds`, `NpzError` for a damaged one."""
    _check_directory(data, bounds.max_members)
    try:
        with zipfile.ZipFile(io.BytesIO(data)) as archive:
            infos = _checked_infos(archive, bounds, len(data))
            members = [_member(archive, info) for info in infos]
            return {member.name: _read_array(archive, member) for member in members}
    except (BoundError, NpzError):
        raise
    except _DAMAGE as exc:
        raise NpzError(f"not a readable .npz file ({first_line(exc)[:200]})") from None


def _check_directory(data: bytes, max_members: int) -> None:
    """Refuse, before `zipfile` parses it, a central directory longer than `max_members` need.

    zipfile takes an end record without a comment from the last 22 bytes, and a zip64 record when its locator sits
    just before; numpy writes neither a comment nor (below 4 GB) a zip64 record, so anything else is refused.
    """
    at = len(data) - _END_RECORD.size
    if at < 0 or data[at : at + 4] != _END_SIGNATURE:
        raise NpzError("not an .npz file (no zip directory at its end)")
    *_, entries, directory_bytes, _offset, comment = _END_RECORD.unpack_from(data, at)
    locator = data[max(at - _LOCATOR_BYTES, 0) : max(at - _LOCATOR_BYTES + 4, 0)]
    if comment or locator == _ZIP64_LOCATOR:
        raise NpzError("not an .npz file as numpy writes it (a zip comment or a zip64 directory)")
    if entries > max_members or directory_bytes > max_members * DIRECTORY_ENTRY_BYTES:
        raise BoundError(
            f"its zip directory lists {entries:,} members in {directory_bytes:,} bytes; at most {max_members} are "
            "expected"
        )


def _checked_infos(archive: zipfile.ZipFile, bounds: NpzBounds, size: int) -> list[zipfile.ZipInfo]:
    infos = archive.infolist()
    if len(infos) > bounds.max_members:
        raise BoundError(f"it has {len(infos):,} members, over the limit of {bounds.max_members}")
    if len({info.filename for info in infos}) != len(infos):
        raise NpzError("a member appears twice")
    for info in infos:
        stem = info.filename.removesuffix(".npy")
        if stem == info.filename or not bounds.names.fullmatch(stem):
            raise NpzError(f"unexpected member {info.filename[:80]!r}")
        if info.flag_bits & 0x1 or info.compress_type not in _METHODS:
            raise NpzError(f"member {info.filename!r} is encrypted or compressed in a way numpy never writes")
    _check_total(sum(info.file_size for info in infos), size, bounds)
    return infos


def _check_total(total: int, size: int, bounds: NpzBounds) -> None:
    if total > bounds.max_unpacked:
        raise BoundError(f"its arrays unpack to {total:,} bytes, over the limit of {bounds.max_unpacked:,}")
    if total > bounds.unpacked_limit(size):
        raise BoundError(
            f"its arrays unpack to {total:,} bytes from {size:,} ({total / max(size, 1):,.0f} : 1), over the limit "
            f"of {bounds.max_ratio:g} : 1 beyond {bounds.small_unpacked:,} bytes (a compression bomb?)"
        )


def _read_exactly(stream: IO[bytes], count: int, what: str) -> bytes:
    data = stream.read(count)
    if len(data) != count:
        raise NpzError(f"{what} ends early")
    return data


def _member(archive: zipfile.ZipFile, info: zipfile.ZipInfo) -> _Member:
    """A member's .npy header, read on its own and checked against the size the directory declares."""
    name = info.filename.removesuffix(".npy")
    with archive.open(info) as stream:
        prefix = _read_exactly(stream, npy.MAGIC_LEN, f"member {name!r}")
        version = npy.read_magic(io.BytesIO(prefix))
        if version not in ((1, 0), (2, 0)):
            raise NpzError(f"member {name!r}: .npy version {version} is not one numpy writes for arrays")
        length_format = "<H" if version == (1, 0) else "<I"
        length_bytes = _read_exactly(stream, struct.calcsize(length_format), f"member {name!r}")
        (length,) = struct.unpack(length_format, length_bytes)
        if length > MAX_HEADER_BYTES:
            raise BoundError(f"member {name!r}: its header has {length:,} bytes, over the limit of {MAX_HEADER_BYTES}")
        header = io.BytesIO(length_bytes + _read_exactly(stream, length, f"member {name!r}"))
    read_header = npy.read_array_header_1_0 if version == (1, 0) else npy.read_array_header_2_0
    shape, fortran, dtype = read_header(header, max_header_size=MAX_HEADER_BYTES)
    member = _Member(info, name, npy.MAGIC_LEN + len(header.getvalue()), dtype, shape, fortran)
    _check_member(member)
    return member


def _check_member(member: _Member) -> None:
    dtype, name = member.dtype, member.name
    if dtype.kind not in _KINDS or dtype.itemsize > 8 or dtype.fields is not None or dtype.subdtype is not None:
        raise NpzError(f"member {name!r} holds {dtype.str!r} values; only integers and floats are read")
    if any(side < 0 for side in member.shape):
        raise NpzError(f"member {name!r} has the shape {member.shape}")
    declared = member.info.file_size
    if declared != member.header_bytes + member.nbytes:
        raise NpzError(
            f"member {name!r} declares {declared:,} bytes but its header says {member.shape} x {dtype.itemsize} bytes "
            f"({member.header_bytes + member.nbytes:,} with the header)"
        )


def _read_array(archive: zipfile.ZipFile, member: _Member) -> np.ndarray:
    """The member's array, read into a buffer of exactly its declared size."""
    raw = np.empty(member.nbytes, dtype=np.uint8)
    with archive.open(member.info) as stream:
        stream.read(member.header_bytes)
        filled = 0
        while filled < member.nbytes:
            chunk = stream.read(min(_CHUNK, member.nbytes - filled))
            if not chunk:
                raise NpzError(f"member {member.name!r} ends after {filled:,} of its {member.nbytes:,} bytes")
            raw[filled : filled + len(chunk)] = np.frombuffer(chunk, dtype=np.uint8)
            filled += len(chunk)
        if stream.read(1):
            raise BoundError(f"member {member.name!r} unpacks to more than the {member.nbytes:,} bytes it declares")
    return raw.view(member.dtype).reshape(member.shape, order="F" if member.fortran else "C")
