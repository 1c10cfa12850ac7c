"""What an export format is: the record each format has in the registry, `physcensis.export.EXPORT_FORMATS`.

A record says what the format writes into a scene folder (a folder or one file, and its name), which function
writes it and from what, the optional extra it needs, a line for help text and whether exports.json records it.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Literal

if TYPE_CHECKING:
    from physcensis.assets.catalogue import Catalogue
    from physcensis.export.bodies import ExportScene
    from physcensis.physics.mujoco_engine import BuiltScene
    from physcensis.scene import Scene

KEYWORDS = ("all", "none")  # what `parse_formats` takes besides the names of formats: no format is named so


@dataclass(frozen=True)
class ExportSource:
    """What a writer is given: the scene, and what it is made from. `bodies` is read (once, before anything is
    written) when a format asked for is made from the bodies; `built` is the caller's model with visuals, if any."""

    scene: Scene
    catalogue: Catalogue
    built: BuiltScene | None = None
    bodies: ExportScene | None = None


Writer = Callable[[ExportSource, Path], Path]


@dataclass(frozen=True)
class Extra:
    """An optional dependency: installed with `pip install 'physcensis[NAME]'`, present when `module` imports."""

    name: str
    module: str

    def installed(self) -> bool:
        return importlib.util.find_spec(self.module) is not None


@dataclass(frozen=True)
class ExportFormat:
    """One export format.

    `output` is the file `export_scene` returns, relative to the scene folder: a format whose output lies in a
    folder (`mjcf/scene.xml`) owns that folder (`entry`, written whole by its writer); any other writes the one file
    `entry`. `made_from` says what its writer reads: the compiled MuJoCo model with visuals (`model`) or the rigid
    bodies of `export/bodies.py` (`bodies`). `recorded`: exports.json keeps the SHA-256 of every file it writes.
    """

    name: str  # in --export / --to, in exports.json and in report.json's "exports"
    output: str
    description: str  # one line, for help text
    write: Writer  # (source, out_dir / entry) -> out_dir / output
    made_from: Literal["model", "bodies"]
    extra: Extra | None = None
    recorded: bool = True

    def __post_init__(self) -> None:
        path = PurePosixPath(self.output)
        if not self.name.isidentifier() or self.name != self.name.lower() or self.name in KEYWORDS:
            raise ValueError(f"export format name {self.name!r}: lower-case letters, digits and _, not all or none")
        if path.is_absolute() or ".." in path.parts or path.as_posix() != self.output or not 0 < len(path.parts) <= 2:
            raise ValueError(f"export format {self.name}: output {self.output!r} is not FILE or FOLDER/FILE")
        if "\n" in self.description or not self.description:
            raise ValueError(f"export format {self.name}: the description is one line")

    @property
    def folder(self) -> bool:
        """Whether the format writes a folder (its `entry`) rather than one file."""
        return len(PurePosixPath(self.output).parts) > 1

    @property
    def entry(self) -> str:
        """The name of what the format writes in a scene folder: its folder, or its file."""
        return PurePosixPath(self.output).parts[0]

    def available(self) -> bool:
        """Whether this installation can write the format (its extra, if it needs one, is installed)."""
        return self.extra is None or self.extra.installed()

    def help_line(self) -> str:
        """`name: description`, with the extra it needs."""
        needs = f", needs the {self.extra.name} extra" if self.extra else ""
        return f"{self.name}: {self.description}{needs}"
