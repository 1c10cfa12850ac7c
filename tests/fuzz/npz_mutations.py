"""Damaged and hostile `.npz` asset copies made from a real one: zip members dropped, duplicated, renamed or swapped,
arrays of other types, shapes and values, forged `.npy` headers, edited metadata, compression bombs, bytes."""

from __future__ import annotations

import io
import json
import re
import warnings
import zipfile
from dataclasses import dataclass
from typing import Any

import numpy as np
from hypothesis import strategies as st
from numpy.lib import format as npy

from tests.fuzz.mutations import Draw, mutated_bytes, mutated_json

BOMB_BYTES = 100 * 2**20  # unpacked: over the harness's 64 MB slack, from about 100 KB
DTYPES = ["<f2", "<f4", "<f8", ">f8", "|i1", "<i4", "<i8", "<u8", "|b1", "<c8", "|S4", "<U2", "<M8[s]"]
ODD_NUMBERS = [np.nan, np.inf, -np.inf, 1e30, -1e30, -1, 2**62, 0]
FORGED_HEADERS = [
    (rb"'shape': \([^)]*\)", b"'shape': (1000000000, 3)"),
    (rb"'shape': \([^)]*\)", b"'shape': (4611686018427387904, 4)"),
    (rb"'shape': \([^)]*\)", b"'shape': (-1, 3)"),
    (rb"'shape': \([^)]*\)", b"'shape': ()"),
    (rb"'descr': '[^']*'", b"'descr': '|O'"),
    (rb"'descr': '[^']*'", b"'descr': '<c16'"),
    (rb"'descr': '[^']*'", b"'descr': [('a', '<f8')]"),
    (rb"'fortran_order': False", b"'fortran_order': True"),
    (rb"'fortran_order': False", b"'fortran_order': __import__('os')"),
]


def members(data: bytes) -> dict[str, bytes]:
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        return {info.filename: archive.read(info) for info in archive.infolist()}


def zipped(items: list[tuple[str, bytes]], method: int = zipfile.ZIP_DEFLATED) -> bytes:
    buffer = io.BytesIO()
    with warnings.catch_warnings(), zipfile.ZipFile(buffer, "w", method) as archive:
        warnings.simplefilter("ignore")  # duplicate names are on purpose
        for name, raw in items:
            archive.writestr(name, raw)
    return buffer.getvalue()


def npy_bytes(array: np.ndarray, pickle: bool = False) -> bytes:
    buffer = io.BytesIO()
    npy.write_array(buffer, array, allow_pickle=pickle)
    return buffer.getvalue()


@dataclass(frozen=True, eq=False)
class NpzSeed:
    """A real payload, read once (its arrays, its metadata): edits start from these, never from a member already
    damaged (reading one could allocate gigabytes in the test itself). And compression bombs made from it: each the
    payload with one member replaced by BOMB_BYTES of zeros (a valid .npy). Made once, in a fixture."""

    data: bytes
    arrays: dict[str, np.ndarray]
    meta: Any
    bombs: tuple[bytes, ...]

    @classmethod
    def of(cls, data: bytes, names: tuple[str, ...] = ("visual_vertices.npy", "meta.npy")) -> NpzSeed:
        seed = members(data)
        with np.load(io.BytesIO(data), allow_pickle=False) as npz:
            arrays = {f"{name}.npy": npz[name] for name in npz.files}
        zeros = npy_bytes(np.zeros((BOMB_BYTES // 24, 3)))
        bombs = tuple(zipped([(n, zeros if n == name else raw) for n, raw in seed.items()]) for name in names)
        return cls(data, arrays, json.loads(arrays["meta.npy"].tobytes()), bombs)

    def __repr__(self) -> str:  # Hypothesis shows the strategy's arguments: not megabytes of them
        return f"NpzSeed({len(self.data):,} bytes, {len(self.bombs)} bombs)"


def _array_variant(draw: Draw, array: np.ndarray) -> bytes:
    op = draw(st.sampled_from(["dtype", "shape", "value", "empty", "object"]))
    if op == "dtype":
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return npy_bytes(array.astype(draw(st.sampled_from(DTYPES))))
    if op == "shape":
        shapes = [(-1,), (1, -1), (-1, 1), (-1, 3, 1)] if array.size else [(0,)]
        return npy_bytes(array.reshape(draw(st.sampled_from(shapes))))
    if op == "value" and array.size and array.dtype.kind in "iuf":
        changed = array.astype(np.float64 if array.dtype.kind == "f" else np.int64).copy()
        flat = changed.reshape(-1)
        value = draw(st.sampled_from(ODD_NUMBERS))
        flat[draw(st.integers(0, flat.size - 1))] = value if changed.dtype.kind == "f" or np.isfinite(value) else -1
        return npy_bytes(changed.astype(array.dtype) if draw(st.booleans()) else changed)
    if op == "empty":
        return npy_bytes(np.zeros((0,) + array.shape[1:], dtype=array.dtype))
    return npy_bytes(np.array([{"a": 1}, None], dtype=object), pickle=True)


def _forged_header(draw: Draw, raw: bytes) -> bytes:
    pattern, new = draw(st.sampled_from(FORGED_HEADERS))
    header_end = raw.find(b"\n", 10) + 1
    header = re.sub(pattern, new, raw[:header_end], count=1)
    return header + raw[header_end:]


def _replaced(items: list[tuple[str, bytes]], name: str, raw: bytes) -> list[tuple[str, bytes]]:
    """`items` with member `name`'s content replaced (or added, when an earlier edit dropped or renamed it)."""
    if all(n != name for n, _ in items):
        return [*items, (name, raw)]
    return [(n, raw if n == name else r) for n, r in items]


def _member_edit(draw: Draw, items: list[tuple[str, bytes]], seed: NpzSeed) -> list[tuple[str, bytes]]:
    op = draw(st.sampled_from(["drop", "duplicate", "rename", "swap", "array", "header", "meta", "junk"]))
    at = draw(st.integers(0, len(items) - 1))
    name, raw = items[at]
    if op == "drop":
        return items[:at] + items[at + 1 :]
    if op == "duplicate":
        return [*items, (name, draw(st.sampled_from([raw, items[0][1]])))]
    if op == "rename":
        new = draw(
            st.sampled_from(["part_999.npy", "part_01.npy", "x.npy", "meta", "../meta.npy", "cavity_opening.npy"])
        )
        return items[:at] + [(new, raw)] + items[at + 1 :]
    if op == "swap":
        other = draw(st.integers(0, len(items) - 1))
        raws = [r for _, r in items]
        raws[at], raws[other] = raws[other], raws[at]
        return [(n, r) for (n, _), r in zip(items, raws, strict=True)]
    if op == "array":
        chosen = draw(st.sampled_from(sorted(seed.arrays)))
        return _replaced(items, chosen, _array_variant(draw, seed.arrays[chosen]))
    if op == "header":
        return items[:at] + [(name, _forged_header(draw, raw))] + items[at + 1 :]
    if op == "meta":
        edited = draw(mutated_json(seed.meta))
        return _replaced(items, "meta.npy", npy_bytes(np.frombuffer(edited, dtype=np.uint8)))
    extra = [(f"part_{k}.npy", npy_bytes(np.zeros((4, 3)))) for k in range(draw(st.sampled_from([1, 300])))]
    return items + extra


def _tolerant_edit(draw: Draw, items: list[tuple[str, bytes]], seed: NpzSeed) -> list[tuple[str, bytes]]:
    """An edit numpy cannot make (a cast it refuses) leaves the members as they are."""
    try:
        return _member_edit(draw, items, seed)
    except (ValueError, TypeError, OverflowError):
        return items


@st.composite
def mutated_npz(draw: Draw, seed: NpzSeed) -> bytes:
    """A damaged copy of the seed's `.npz` payload."""
    data = seed.data
    op = draw(st.sampled_from(["members", "members", "members", "bytes", "bomb"]))
    if op == "bomb":
        payload = draw(st.sampled_from(seed.bombs))
        return draw(mutated_bytes(payload)) if draw(st.booleans()) else payload
    if op == "bytes":
        return draw(mutated_bytes(data))
    items = list(members(data).items())
    for _ in range(draw(st.integers(1, 3))):
        if items:
            items = _tolerant_edit(draw, items, seed)
    method = draw(st.sampled_from([zipfile.ZIP_DEFLATED, zipfile.ZIP_STORED]))
    payload = zipped(items, method)
    return draw(mutated_bytes(payload)) if draw(st.integers(0, 3)) == 0 else payload
