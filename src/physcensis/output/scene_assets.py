"""A scene folder's own copies of the library assets it uses, so it works on a machine without the library.

Built-in and generated assets are rebuilt from their ids and descriptions; a user library's asset is not, so
`write_scene_assets` copies each one (visual mesh, collision parts, physical ranges; the `.npz` of the asset cache)
into `assets/<id>.npz` and records its hash and the mesh file it came from in scene.json. `open_scene` reads a
scene file with those copies in front of the catalogue: the scene simulates, renders and exports as it was solved,
whether or not the library is loaded (or has changed since).

Scene folders are shared, so a copy is untrusted: it is read as a regular file inside the folder (`read_in_folder`),
decoded within bounds (`serialize.asset_from_bytes`: no compression bomb, shapes and types checked before anything is
allocated) and checked as an import checks a mesh (`copy_checks`). Any refusal is an AssetError naming the file.
"""

from __future__ import annotations

import hashlib
import logging
from pathlib import Path

from physcensis.assets.catalogue import Catalogue, default_catalogue
from physcensis.assets.copy_checks import check_copied_asset
from physcensis.assets.errors import AssetError
from physcensis.assets.meshfile import first_line
from physcensis.assets.model import Asset
from physcensis.assets.serialize import asset_from_bytes, asset_to_bytes
from physcensis.fileio import BoundError, read_bounded, read_in_folder
from physcensis.scene import AssetCopy, Scene, load_scene

log = logging.getLogger(__name__)
ASSETS_DIR = "assets"
MAX_ASSET_BYTES = 512 * 1024 * 1024  # one asset's copy: a 2,000,000-triangle mesh and its hulls
MAX_SOURCE_HASH_BYTES = 100 * 1024 * 1024  # the library's mesh file is hashed up to the importer's own bound


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _source_hash(source: str) -> str | None:
    try:
        return _sha256(read_bounded(Path(source), MAX_SOURCE_HASH_BYTES, "mesh file"))
    except (OSError, BoundError):  # moved or unreadable since import: the copy is what counts
        return None


def _library_assets(scene: Scene, catalogue: Catalogue) -> dict[str, Asset]:
    """The scene's assets that only a user library can rebuild: not built-in, not generated from a description."""
    out: dict[str, Asset] = {}
    for obj in scene.objects:
        if obj.asset in out or catalogue.is_builtin(obj.asset) or obj.asset not in catalogue:
            continue
        asset = catalogue.get(obj.asset)
        if not asset.generated:
            out[obj.asset] = asset
    return out


def write_scene_assets(scene: Scene, catalogue: Catalogue, folder: Path) -> Scene:
    """Copy the scene's library assets into `folder/assets/`; the scene with their records (unchanged without any)."""
    assets = _library_assets(scene, catalogue)
    if not assets:
        return scene
    (folder / ASSETS_DIR).mkdir(exist_ok=True)
    records = {}
    for asset_id, asset in sorted(assets.items()):
        data = asset_to_bytes(asset)
        name = f"{ASSETS_DIR}/{asset_id}.npz"
        (folder / name).write_bytes(data)  # folder is a staging folder: published whole, or not at all
        source = asset.source if asset.source and asset.source != "builtin" else None
        records[asset_id] = AssetCopy(
            file=name, sha256=_sha256(data), source=source, source_sha256=_source_hash(source) if source else None
        )
    return scene.model_copy(update={"assets": records})


def _read_copy(folder: Path, asset_id: str, record: AssetCopy) -> Asset:
    name = f"{ASSETS_DIR}/{asset_id}.npz"  # from the id, never from a path in the file
    path = folder / name
    if not (path.exists() or path.is_symlink()):
        raise AssetError(f"{path}: the scene's copy of asset {asset_id!r} is missing")
    try:
        data = read_in_folder(folder, name, MAX_ASSET_BYTES, "file")
    except BoundError as exc:
        raise AssetError(f"{path}: cannot read the scene's copy of asset {asset_id!r} ({exc})") from None
    if _sha256(data) != record.sha256:
        raise AssetError(f"{path}: the copy of asset {asset_id!r} does not match its hash in scene.json")
    try:
        asset = asset_from_bytes(data)
        check_copied_asset(asset)
    except (ValueError, AssetError) as exc:  # BoundError, NpzError and the model's own checks are ValueErrors
        raise AssetError(f"{path}: {exc}") from None
    except Exception as exc:  # anything else numpy or trimesh say about a damaged payload
        raise AssetError(f"{path}: the copy of asset {asset_id!r} is damaged ({first_line(exc)})") from None
    if asset.id != asset_id:
        raise AssetError(f"{path}: holds asset {asset.id!r}, not {asset_id!r}")
    return asset


def scene_catalogue(scene: Scene, folder: Path, base: Catalogue | None = None) -> Catalogue:
    """`base` (the default catalogue) with the scene folder's own asset copies in front of it."""
    base = base or default_catalogue()
    if not scene.assets:
        return base
    return base.with_assets(_read_copy(folder, asset_id, record) for asset_id, record in scene.assets.items())


def open_scene(path: str | Path, base: Catalogue | None = None) -> tuple[Scene, Catalogue]:
    """A scene file (or scene folder) and the catalogue that holds every asset it uses."""
    path = Path(path)
    scene_path = path / "scene.json" if path.is_dir() else path
    scene = load_scene(scene_path)
    return scene, scene_catalogue(scene, scene_path.parent, base)
