"""A scene folder's asset copies (`assets/<id>.npz`) come from elsewhere: a hostile or broken copy is refused.

Each hostile copy below is recorded in scene.json with its own hash, as a folder crafted on purpose would be. Every
command that reads the copies (render, export, eval settle, stability) must refuse it with one line naming the file,
exit code 2, no traceback and nothing written: a compression bomb before anything is unpacked, a copy an import
would not have made (faces out of range, NaN or absurd coordinates, wrong shapes or types) before any engine sees it.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import io
import json
import logging
import re
import struct
import zipfile
import zlib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh
import yaml
from typer.testing import CliRunner

from physcensis.assets.cache import AssetCache
from physcensis.assets.npz import NpzBounds, NpzError, read_npz
from physcensis.assets.serialize import PAYLOAD_BOUNDS, asset_from_bytes, asset_to_bytes
from physcensis.cli import app
from physcensis.fileio import BoundError
from physcensis.output import open_scene

runner = CliRunner()
COPY = "assets/lib_block.npz"
Arrays = dict[str, Any]


@pytest.fixture(scope="module")
def solved(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A scene folder solved with one asset of a user library (a 12 x 9 x 4 cm block), so it carries its copy."""
    root = tmp_path_factory.mktemp("copies")
    (root / "library" / "meshes").mkdir(parents=True)
    block = trimesh.creation.box((0.12, 0.09, 0.04))
    (root / "library" / "meshes" / "block.stl").write_bytes(block.export(file_type="stl"))
    entry = {"file": "meshes/block.stl", "id": "lib_block", "category": "wooden block"}
    (root / "library" / "library.yaml").write_text(yaml.safe_dump({"assets": [entry]}))
    program = {
        "support": {"kind": "table", "size": [0.6, 0.4]},
        "program": [
            ["block", "asset:lib_block"],
            ["block", "PLACE-ON-BASE", "root", {"x": 0.1, "y": 0.05}],
            ["block", "FACING-FRONT", "root", {}],
        ],
    }
    (root / "program.json").write_text(json.dumps(program))
    out = root / "scene"
    args = ["solve", str(root / "program.json"), "--out", str(out), "--library", str(root / "library"), "--no-physics"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    assert (out / COPY).is_file()
    return out


def _arrays(solved: Path) -> Arrays:
    with np.load(solved / COPY, allow_pickle=False) as npz:
        return {name: npz[name] for name in npz.files}


def _saved(arrays: Arrays, pickle: bool = False) -> bytes:
    buffer = io.BytesIO()
    np.savez_compressed(buffer, allow_pickle=pickle, **arrays)
    return buffer.getvalue()


def _shared_folder(solved: Path, tmp_path: Path, data: bytes) -> Path:
    """A copy of the scene folder (scene.json and assets/) whose copy of lib_block is `data`, its hash recorded."""
    folder = tmp_path / "shared"
    (folder / "assets").mkdir(parents=True)
    scene = json.loads((solved / "scene.json").read_text())
    scene["assets"]["lib_block"]["sha256"] = hashlib.sha256(data).hexdigest()
    (folder / "scene.json").write_text(json.dumps(scene))
    (folder / COPY).write_bytes(data)
    return folder


def _changed(solved: Path, **arrays: Any) -> bytes:
    return _saved(_arrays(solved) | arrays)


def _meta_changed(solved: Path, **fields: Any) -> bytes:
    arrays = _arrays(solved)
    meta = json.loads(arrays["meta"].tobytes()) | fields
    return _saved(arrays | {"meta": np.frombuffer(json.dumps(meta).encode(), dtype=np.uint8)})


def _vertices(solved: Path, row: int, value: float) -> bytes:
    vertices = _arrays(solved)["visual_vertices"].copy()
    vertices[row] = value
    return _changed(solved, visual_vertices=vertices)


def _faces(solved: Path, value: int) -> bytes:
    faces = _arrays(solved)["visual_faces"].copy()
    faces[3, 1] = value
    return _changed(solved, visual_faces=faces)


def _declared_size(data: bytes, member: str, change: int) -> bytes:
    """`data` with the unpacked size its zip directory declares for `member` changed by `change` bytes (and, for a
    smaller size, the CRC of what is left: the zip layer then finds nothing wrong)."""
    content = zipfile.ZipFile(io.BytesIO(data)).read(member)
    at = struct.unpack_from("<L", data, len(data) - 6)[0]  # the end record's directory offset: its first entry
    while data[at + 46 : at + 46 + len(member)] != member.encode():
        name_length, extra_length, comment_length = struct.unpack_from("<3H", data, at + 28)
        at += 46 + name_length + extra_length + comment_length
    crc = zlib.crc32(content[: len(content) + change]) if change < 0 else struct.unpack_from("<L", data, at + 16)[0]
    return (
        data[: at + 16]
        + struct.pack("<L", crc)
        + data[at + 20 : at + 24]
        + struct.pack("<L", len(content) + change)
        + data[at + 28 :]
    )


def _with_members(solved: Path, count: int) -> bytes:
    extra = {f"part_{i}": np.zeros((4, 3)) for i in range(10, 10 + count)}
    return _saved(_arrays(solved) | extra)


def _symlinked(solved: Path, tmp_path: Path) -> Path:
    folder = _shared_folder(solved, tmp_path, (solved / COPY).read_bytes())
    outside = tmp_path / "elsewhere.npz"
    (folder / COPY).rename(outside)
    (folder / COPY).symlink_to(outside)
    return folder


HOSTILE: dict[str, tuple[Callable[[Path], bytes], str]] = {
    "bomb": (  # 240 MB of zeros in about 230 kB
        lambda s: _changed(s, visual_vertices=np.broadcast_to(np.float64(0), (10_000_000, 3))),
        r"its arrays unpack to 240,00\d,\d+ bytes from \d+,\d+ \([\d,]+ : 1\), over the limit of 3 : 1 beyond",
    ),
    "bomb over the absolute bound": (  # 408 MB of zeros in about 400 kB
        lambda s: _changed(s, visual_faces=np.broadcast_to(np.int64(0), (17_000_000, 3))),
        r"its arrays unpack to 408,\d+,\d+ bytes, over the limit of 385,048,576$",
    ),
    "declared size larger than the array": (
        lambda s: _declared_size(_changed(s), "visual_vertices.npy", 24),
        r"member 'visual_vertices' declares \d+ bytes but its header says \(8, 3\) x 8 bytes",
    ),
    "declared size smaller than the array": (
        lambda s: _declared_size(_changed(s), "visual_faces.npy", -12),
        r"member 'visual_faces' declares \d+ bytes but its header says \(12, 3\) x 4 bytes",
    ),
    "object dtype": (
        lambda s: _saved(_arrays(s) | {"visual_faces": _arrays(s)["visual_faces"].astype(object)}, pickle=True),
        r"member 'visual_faces' holds '\|O' values; only integers and floats are read",
    ),
    "unexpected member": (
        lambda s: _changed(s, evil=np.zeros(3)),
        r"unexpected member 'evil.npy'",
    ),
    "too many members": (lambda s: _with_members(s, 300), r"its zip directory lists 30\d members"),
    "face index out of range": (
        lambda s: _faces(s, 9999),
        r"a face refers to vertex 10000 but the file has only 8",
    ),
    "negative face index": (lambda s: _faces(s, -1), r"a face has a negative vertex index"),
    "float faces": (
        lambda s: _changed(s, visual_faces=_arrays(s)["visual_faces"].astype(np.float64)),
        r"array 'visual_faces' holds float64 values, not integers",
    ),
    "NaN vertex": (lambda s: _vertices(s, 2, np.nan), r"1 of 8 vertices have NaN or infinite coordinates"),
    "1e9 coordinates": (
        lambda s: _vertices(s, 5, 1e9),
        r"a vertex reaches 1e\+09 m from the asset's origin; an asset lies within 20 m",
    ),
    "faces of the wrong shape": (
        lambda s: _changed(s, visual_faces=_arrays(s)["visual_faces"].reshape(-1, 2)),
        r"array 'visual_faces' has the shape \(18, 2\), not \(N, 3\)",
    ),
    "vertices of the wrong shape": (
        lambda s: _changed(s, visual_vertices=_arrays(s)["visual_vertices"][:, :2]),
        r"array 'visual_vertices' has the shape \(8, 2\), not \(N, 3\)",
    ),
    "NaN collision vertex": (
        lambda s: _changed(s, part_0=np.where(np.arange(3) == 1, np.nan, _arrays(s)["part_0"])),
        r"collision part 0 has NaN or infinite coordinates",
    ),
    "negative friction": (
        lambda s: _meta_changed(s, friction_range=[-1.0, 0.5]),
        r"its friction range \[-1, 0\.5\] is not an ordered range in \(0, 10\]",
    ),
    "NaN mass": (lambda s: _meta_changed(s, mass=float("nan")), r"metadata mass: Input should be a finite number"),
}


@functools.cache
def _payload(solved: Path, case: str) -> bytes:
    return HOSTILE[case][0](solved)


def _refused(result: Any, folder: Path, reason: str) -> None:
    """Exit 2 with one line naming the copy and matching `reason`, and no traceback."""
    assert result.exit_code == 2, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert "Traceback" not in result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {folder / COPY}: "), result.output
    assert re.search(reason, lines[0]), lines[0]


@pytest.mark.parametrize("case", HOSTILE)
def test_render_refuses_a_hostile_copy_and_writes_nothing(solved: Path, tmp_path: Path, case: str) -> None:
    folder = _shared_folder(solved, tmp_path, _payload(solved, case))
    reason = HOSTILE[case][1]
    out = tmp_path / "view.png"
    _refused(runner.invoke(app, ["render", str(folder), "--out", str(out)]), folder, reason)
    assert not out.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["shared"]


@pytest.mark.parametrize("case", HOSTILE)
def test_export_refuses_a_hostile_copy_and_writes_nothing(solved: Path, tmp_path: Path, case: str) -> None:
    folder = _shared_folder(solved, tmp_path, _payload(solved, case))
    reason = HOSTILE[case][1]
    out = tmp_path / "exported"
    _refused(runner.invoke(app, ["export", str(folder), "--to", "mjcf,glb", "--out", str(out)]), folder, reason)
    assert not out.exists() and sorted(p.name for p in tmp_path.iterdir()) == ["shared"]


@pytest.mark.parametrize("case", ["bomb", "face index out of range"])
@pytest.mark.parametrize("command", [["eval", "settle"], ["stability"]])
def test_settle_and_stability_refuse_a_hostile_copy(
    solved: Path, tmp_path: Path, case: str, command: list[str]
) -> None:
    folder = _shared_folder(solved, tmp_path, _payload(solved, case))
    reason = HOSTILE[case][1]
    _refused(runner.invoke(app, [*command, str(folder)]), folder, reason)


@pytest.mark.parametrize("command", ["render", "export"])
def test_a_symlinked_copy_is_refused(solved: Path, tmp_path: Path, command: str) -> None:
    folder = _symlinked(solved, tmp_path)
    out = tmp_path / ("view.png" if command == "render" else "exported")
    extra = ["--to", "glb"] if command == "export" else []
    result = runner.invoke(app, [command, str(folder), "--out", str(out), *extra])
    _refused(result, folder, r"cannot read the scene's copy of asset 'lib_block' \(file: is a symbolic link; refused\)")
    assert not out.exists()


def test_the_copy_as_written_still_opens_unchanged(solved: Path, tmp_path: Path) -> None:
    folder = _shared_folder(solved, tmp_path, (solved / COPY).read_bytes())
    scene, catalogue = open_scene(folder)
    asset, written = catalogue.get("lib_block"), _arrays(solved)
    assert np.array_equal(asset.visual.vertices, written["visual_vertices"])
    assert np.array_equal(asset.visual.faces, written["visual_faces"]) and asset.visual.faces.shape == (12, 3)
    assert asset.size == pytest.approx((0.12, 0.09, 0.04)) and [o.asset for o in scene.placed] == ["lib_block"]


# -- the bounded reader itself, and the asset cache that reads the same payloads --------------------------------------
def _bounds(**changes: Any) -> NpzBounds:
    fields = {name: getattr(PAYLOAD_BOUNDS, name) for name in NpzBounds.__dataclass_fields__} | changes
    return NpzBounds(**fields)


def test_only_a_zip_directory_as_numpy_writes_it_is_read(solved: Path) -> None:
    data = (solved / COPY).read_bytes()
    end = len(data) - 22  # the end record
    for hostile, reason in (
        (data + b"evil", "no zip directory at its end"),  # zipfile would search back for one: a directory of any size
        (data[:-1], "no zip directory at its end"),
        (data[:-2] + struct.pack("<H", 4), "a zip comment or a zip64 directory"),
        (data[:end] + b"PK\x06\x07" + bytes(16) + data[end:], "a zip comment or a zip64 directory"),
    ):
        with pytest.raises(NpzError, match=reason):
            read_npz(hostile, PAYLOAD_BOUNDS)


def test_the_ratio_bound_spares_small_payloads_and_stops_large_ones(solved: Path) -> None:
    data = _changed(solved, visual_vertices=np.zeros((40_000, 3)))  # 960 kB of zeros: a bomb, but a small one
    assert read_npz(data, PAYLOAD_BOUNDS)["visual_vertices"].shape == (40_000, 3)
    with pytest.raises(BoundError, match=r"over the limit of 3 : 1 beyond 100,000 bytes"):
        read_npz(data, _bounds(small_unpacked=100_000))


def test_a_payload_that_compresses_too_well_is_written_uncompressed(solved: Path) -> None:
    asset = asset_from_bytes((solved / COPY).read_bytes())
    flat = np.zeros((1_000_000, 3))  # 24 MB that compress to almost nothing
    flat[:8] = asset.visual.vertices
    regular = trimesh.Trimesh(flat, asset.visual.faces, process=False)
    data = asset_to_bytes(dataclasses.replace(asset, visual=regular))
    assert len(data) > 24_000_000  # stored: any reader accepts what physcensis writes
    assert asset_from_bytes(data).visual.vertices.shape == (1_000_000, 3)


def test_the_cache_refuses_a_bomb_and_rebuilds(solved: Path, tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    cache = AssetCache(tmp_path)
    cache.folder.mkdir(parents=True)
    cache.path("lib_block-bomb").write_bytes(_payload(solved, "bomb"))
    with caplog.at_level(logging.WARNING):
        assert cache.load("lib_block-bomb") is None
    assert "damaged entry" in caplog.text and "over the limit of 3 : 1" in caplog.text
    assert cache.load("missing") is None
