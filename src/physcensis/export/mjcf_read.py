"""A scene folder's MJCF export read back as untrusted input, and checked against the folder's scene.json.

Every file is read with `read_in_folder` (inside the folder, no link, bounded) and handed to MuJoCo as bytes, so
MuJoCo never opens a file itself. The XML is read once with expat before MuJoCo sees it: no DOCTYPE or entity
declaration, only the elements physcensis writes (no include, model, plugin, replicate, composite, flex, frame,
hfield or skin), files only as plain `.stl` names of meshes, bounded depth, element count and the sizes that make
MuJoCo allocate (textures, offscreen buffer). Its free bodies must be the scene's placed objects at the scene's poses.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn
from xml.parsers import expat

from physcensis.errors import ExportMismatchError
from physcensis.export import EXPORT_FORMATS
from physcensis.export.manifest import (
    Pose,
    RecordedExport,
    check_recorded_file,
    check_scene_against_manifest,
    pose_difference,
    read_manifest,
    reexport_hint,
    scene_poses,
)
from physcensis.fileio import BoundError, read_in_folder
from physcensis.scene import Scene

MJCF_DIR = EXPORT_FORMATS["mjcf"].entry  # mjcf
XML_FILE = EXPORT_FORMATS["mjcf"].output  # mjcf/scene.xml
MAX_XML_BYTES = 32 * 2**20
MAX_MESH_BYTES = 100_000_000  # one mesh file, as for an imported mesh
MAX_MESHES_BYTES = 512 * 2**20  # all of them
MAX_DEPTH = 16  # physcensis writes 4 levels (mujoco, worldbody, body, geom)
ELEMENTS_PER_OBJECT = 1_000  # a placed object is a body, its parts' geoms and meshes: a few hundred at most
BASE_ELEMENTS = 1_000
MAX_TEXTURES = 8
MAX_MAGNITUDE = 1e9  # any number in an attribute (a mass, a size, a friction): NaN and infinities are refused
# The elements physcensis's MJCF holds (and a few as harmless: site, camera, freejoint, rgba, scale, flag).
ELEMENTS = frozenset(
    {
        *("mujoco", "compiler", "option", "flag", "statistic", "visual", "global", "quality", "headlight", "map"),
        *("rgba", "scale", "asset", "texture", "material", "mesh", "worldbody", "body", "inertial", "joint"),
        *("freejoint", "geom", "site", "camera", "light"),
    }
)
# Attribute values that make MuJoCo allocate in proportion (pixels, samples) are bounded.
BOUNDS = {
    ("global", "offwidth"): 4096,
    ("global", "offheight"): 4096,
    ("quality", "offsamples"): 16,
    ("quality", "shadowsize"): 8192,
    ("texture", "width"): 4096,
    ("texture", "height"): 6 * 4096,  # a skybox stacks its six faces
}
_PATH_ATTRIBUTES = frozenset({"assetdir", "meshdir", "texturedir"})
_ALLOWED_PATHS = frozenset({("mesh", "file"), ("compiler", "meshdir")})
_GENERATED_MESH = frozenset({"builtin", "params"})  # a mesh MuJoCo makes at a size the file does not bound
_ORIENTATIONS = ("euler", "axisangle", "xyaxes", "zaxis")
_MESH_FILE = re.compile(r"[A-Za-z0-9_.-]{1,200}\.stl", re.IGNORECASE)
_DIR_PART = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9_.-]{0,99}")
_DECLARATION = re.compile(r"<!(?!--|\[CDATA\[)")


@dataclass(frozen=True)
class MjcfExport:
    """What MuJoCo needs to load the export without touching the file system: the XML, and every file it names as
    bytes (a spec's `assets`, keyed as MuJoCo looks them up: meshdir/name)."""

    xml: str
    assets: dict[str, bytes]


def read_mjcf(folder: Path, scene: Scene) -> MjcfExport:
    """The folder's `mjcf/` export, read with bounds and refused (ExportMismatchError, naming the file) unless it is
    safe to load and belongs to `scene`: the same objects at the same poses and, when the folder records its
    exports (exports.json), a scene.json and files unchanged since they were written."""
    manifest = read_manifest(folder)
    record = manifest.exports.get("mjcf") if manifest is not None else None
    if manifest is not None:
        check_scene_against_manifest(folder, manifest, scene, "mjcf")
    data = _read(folder, XML_FILE, MAX_XML_BYTES)
    xml = _text(folder, data)
    parsed = _Walk(folder, BASE_ELEMENTS + ELEMENTS_PER_OBJECT * len(scene.placed)).parse(xml)
    check_poses(folder, parsed.poses, scene)
    check_recorded_file(folder, XML_FILE, data, record, "mjcf")
    return MjcfExport(xml, _read_meshes(folder, parsed, record))


def check_poses(folder: Path, poses: dict[str, Pose], scene: Scene) -> None:
    """Refuse an MJCF whose free bodies are not the scene's placed objects at the scene's poses."""
    difference = pose_difference(poses, scene_poses(scene), "scene.json")
    if difference is not None:
        raise ExportMismatchError(f"{folder / XML_FILE}: {difference}; {reexport_hint(folder, 'mjcf')}")


def _read(folder: Path, relative: str, limit: int) -> bytes:
    try:
        return read_in_folder(folder, relative, limit)
    except BoundError as exc:
        raise ExportMismatchError(f"{folder}: {exc}") from None


def _text(folder: Path, data: bytes) -> str:
    try:
        xml = data.decode("utf-8")
    except UnicodeDecodeError:
        raise ExportMismatchError(f"{folder / XML_FILE}: not UTF-8 text, as MuJoCo writes it") from None
    if _DECLARATION.search(xml):
        raise ExportMismatchError(f"{folder / XML_FILE}: holds a DOCTYPE or ENTITY declaration; refused")
    return xml


class _Walk:
    """One pass of expat over the XML, keeping only the stack of open tags and what the checks need: the free bodies
    directly under worldbody, the mesh files and their folder. Any refusal raises from inside the parse."""

    def __init__(self, folder: Path, max_elements: int) -> None:
        self.folder = folder
        self.max_elements = max_elements
        self.stack: list[str] = []
        self.elements = self.textures = 0
        self.body: dict[str, str] | None = None  # the open body directly under worldbody
        self.free = False
        self.poses: dict[str, Pose] = {}
        self.meshes: list[str] = []
        self.meshdir = ""

    def refuse(self, what: str) -> NoReturn:
        raise ExportMismatchError(f"{self.folder / XML_FILE}: {what}; {reexport_hint(self.folder, 'mjcf')}")

    def parse(self, xml: str) -> _Walk:
        parser = expat.ParserCreate()
        parser.StartElementHandler = self.start
        parser.EndElementHandler = self.end
        parser.StartDoctypeDeclHandler = lambda *_: self.refuse("holds a DOCTYPE declaration")
        parser.EntityDeclHandler = lambda *_: self.refuse("holds an ENTITY declaration")
        try:
            parser.Parse(xml, True)
        except expat.ExpatError as exc:
            problem = f"{expat.errors.messages[exc.code]}, line {exc.lineno}"
            raise ExportMismatchError(f"{self.folder / XML_FILE}: not well-formed XML ({problem})") from None
        return self

    def start(self, tag: str, attributes: dict[str, str]) -> None:
        self.check(tag, attributes)
        if tag == "compiler" and "meshdir" in attributes:
            self.meshdir = _meshdir(attributes["meshdir"], self.refuse)
        elif tag == "mesh" and "file" in attributes:
            self.meshes.append(_mesh_file(attributes, self.refuse))
        elif tag == "body" and self.stack == ["mujoco", "worldbody"]:
            self.body, self.free = attributes, False
        elif self.body is not None and len(self.stack) == 3 and _is_free_joint(tag, attributes):
            self.free = True
        self.stack.append(tag)

    def end(self, tag: str) -> None:
        self.stack.pop()
        if tag != "body" or self.stack != ["mujoco", "worldbody"] or self.body is None:
            return
        if self.free:
            name, pose = _body_pose(self.body, self.refuse)
            if name in self.poses:
                self.refuse(f"two free bodies are named {name}")
            self.poses[name] = pose
        self.body = None

    def check(self, tag: str, attributes: dict[str, str]) -> None:
        if not self.stack and tag != "mujoco":
            self.refuse(f"its root is <{tag}>, not <mujoco>")
        if tag not in ELEMENTS:
            self.refuse(f"holds an element <{tag}>, which physcensis never writes")
        if tag == "mujoco" and self.stack:
            self.refuse("holds a <mujoco> element inside another")
        if len(self.stack) >= MAX_DEPTH:
            self.refuse(f"nests elements more than {MAX_DEPTH} deep")
        self.elements += 1
        self.textures += tag == "texture"
        if self.elements > self.max_elements or self.textures > MAX_TEXTURES:
            self.refuse(
                f"holds more elements than a scene of its objects needs ({self.max_elements:,}, "
                f"{MAX_TEXTURES} textures at most)"
            )
        for name, value in attributes.items():
            _check_attribute(tag, name, value, self.refuse)


def _check_attribute(tag: str, name: str, value: str, refuse: Callable[[str], NoReturn]) -> None:
    if (name.startswith("file") or name in _PATH_ATTRIBUTES) and (tag, name) not in _ALLOWED_PATHS:
        refuse(f"<{tag}> names a file or folder in {name!r}, which physcensis never writes")
    if tag == "mesh" and name in _GENERATED_MESH:
        refuse(f"<mesh> asks MuJoCo to generate it ({name!r}), which physcensis never writes")
    limit = BOUNDS.get((tag, name))
    if limit is not None and not all(_number(v) <= limit for v in value.split()):
        refuse(f"<{tag}> {name}={value[:40]!r} is over the limit of {limit}")
    numbers = _numbers(value)
    if numbers is not None and not all(abs(v) <= MAX_MAGNITUDE for v in numbers):
        refuse(f"<{tag}> {name}={value[:40]!r} holds a number that is not finite or over {MAX_MAGNITUDE:g}")


def _numbers(text: str) -> list[float] | None:
    """The numbers of an attribute that is a list of numbers (NaN and infinities included), else None."""
    try:
        return [float(part) for part in text.split()]
    except ValueError:
        return None


def _number(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        return math.inf
    return value if math.isfinite(value) else math.inf


def _meshdir(value: str, refuse: Callable[[str], NoReturn]) -> str:
    parts = value.strip("/").split("/")
    if value.startswith("/") or not all(_DIR_PART.fullmatch(p) for p in parts):
        refuse(f"meshdir {value[:80]!r} is not a plain folder inside mjcf/")
    return "/".join(parts)


def _mesh_file(attributes: dict[str, str], refuse: Callable[[str], NoReturn]) -> str:
    name = attributes["file"]
    if not _MESH_FILE.fullmatch(name):
        refuse(f"mesh file {name[:80]!r} is not a plain .stl file name, as physcensis writes them")
    if attributes.get("content_type", "model/stl") != "model/stl":
        refuse(f"mesh {name} has content type {attributes['content_type'][:40]!r}, not model/stl")
    return name


def _is_free_joint(tag: str, attributes: dict[str, str]) -> bool:
    return tag == "freejoint" or (tag == "joint" and attributes.get("type") == "free")


def _body_pose(body: dict[str, str], refuse: Callable[[str], NoReturn]) -> tuple[str, Pose]:
    name = body.get("name")
    if not name:
        refuse("holds a free body without a name")
    turned = [key for key in _ORIENTATIONS if key in body]
    if turned:
        refuse(f"body {name} gives its orientation as {turned[0]}, physcensis writes quat")
    position = _vector(body.get("pos", "0 0 0"), 3, f"body {name}'s pos", refuse)
    quaternion = _vector(body.get("quat", "1 0 0 0"), 4, f"body {name}'s quat", refuse)
    return name, Pose(position, quaternion)


def _vector(text: str, size: int, what: str, refuse: Callable[[str], NoReturn]) -> tuple[float, ...]:
    values = tuple(_number(v) for v in text.split())
    if len(values) != size or not all(math.isfinite(v) for v in values):
        refuse(f"{what} is not {size} finite numbers")
    return values


def _read_meshes(folder: Path, parsed: _Walk, record: RecordedExport | None) -> dict[str, bytes]:
    assets: dict[str, bytes] = {}
    total = 0
    for name in dict.fromkeys(parsed.meshes):
        inside = f"{parsed.meshdir}/{name}" if parsed.meshdir else name
        relative = f"{MJCF_DIR}/{inside}"
        data = _read(folder, relative, MAX_MESH_BYTES)
        total += len(data)
        if total > MAX_MESHES_BYTES:
            raise ExportMismatchError(f"{folder / MJCF_DIR}: its meshes hold over {MAX_MESHES_BYTES:,} bytes; refused")
        check_recorded_file(folder, relative, data, record, "mjcf")
        assets[inside] = data
    return assets
