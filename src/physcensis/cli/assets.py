"""`physcensis assets ...`: list, show, search, import and render the asset catalogue."""

from __future__ import annotations

import json
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.markup import escape
from rich.table import Table

from physcensis.assets.errors import AssetError
from physcensis.cli.errors import err_console, fail, finish, print_warning, reports_errors
from physcensis.cli.options import LibraryOption, console, with_libraries

if TYPE_CHECKING:  # the catalogue takes seconds to import: `physcensis --help` does without it
    from physcensis.assets.catalogue import Catalogue
    from physcensis.assets.model import Asset

assets_app = typer.Typer(help="Browse, search, import and render assets.", no_args_is_help=True, add_completion=False)
LibraryOpt = LibraryOption


def _catalogue(libraries: list[Path] | None) -> Catalogue:
    return with_libraries(libraries)


def _fmt_size(size: tuple[float, float, float]) -> str:
    return " x ".join(f"{v * 100:.1f}" for v in size) + " cm"


def asset_summary(asset: Asset) -> dict[str, Any]:
    """JSON-ready description of an asset (no geometry)."""
    return {
        "id": asset.id,
        "category": asset.category,
        "kind": asset.kind,
        "description": asset.description,
        "size": list(asset.size),
        "mass": asset.mass,
        "mass_range": list(asset.mass_range),
        "friction_range": list(asset.friction_range),
        "com": list(asset.com),
        "com_shift_range": list(asset.com_shift_range),
        "support_probability": asset.support_probability,
        "has_front": asset.has_front,
        "container": asset.is_container,
        "cavity": None
        if asset.cavity is None
        else {
            "floor_height": asset.cavity.floor_height,
            "depth": asset.cavity.depth,
            "opening": asset.cavity.opening.tolist(),
        },
        "collision_parts": [p.kind for p in asset.collision],
        "visual_faces": len(asset.visual.faces),
        "tags": list(asset.tags),
        "synonyms": list(asset.synonyms),
        "generated": asset.generated,
        "guessed": sorted(asset.guessed),
        "source": asset.source,
    }


@assets_app.command("list")
@reports_errors
def list_assets(
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    category: Annotated[str | None, typer.Option("--category", "-c", help="only this category")] = None,
    library: LibraryOpt = None,
) -> None:
    """List the catalogue (no geometry is generated)."""
    catalogue = _catalogue(library)
    entries = [e for e in catalogue.entries() if category is None or e.category == category]
    if category is not None and not entries:
        raise AssetError(f"no category {category!r}; categories: {', '.join(catalogue.categories())}")
    if as_json:
        rows = [
            {
                "id": e.id,
                "category": e.category,
                "kind": e.kind,
                "description": e.description,
                "size": list(e.size),
                "source": e.source,
            }
            for e in entries
        ]
        payload = {"count": len(rows), "categories": sorted({e.category for e in entries}), "assets": rows}
        sys.stdout.write(json.dumps(payload, indent=1) + "\n")
        return
    table = Table("id", "category", "kind", "size", "description")
    for e in entries:
        table.add_row(e.id, escape(e.category), e.kind, _fmt_size(e.size), escape(e.description))
    console.print(table)
    console.print(f"{len(entries)} assets in {len({e.category for e in entries})} categories")


@assets_app.command("show")
@reports_errors
def show(
    asset_id: Annotated[str, typer.Argument(help="asset id")],
    as_json: Annotated[bool, typer.Option("--json")] = False,
    library: LibraryOpt = None,
) -> None:
    """Show one asset's annotations and geometry summary."""
    asset = _catalogue(library).get(asset_id)
    summary = asset_summary(asset)
    if as_json:
        sys.stdout.write(json.dumps(summary, indent=1) + "\n")
        return
    table = Table("field", "value", show_header=False)
    for key, value in summary.items():
        if key == "cavity" and value is not None:
            value = f"floor {value['floor_height'] * 100:.1f} cm, depth {value['depth'] * 100:.1f} cm"
        elif key == "size":
            value = _fmt_size(asset.size)
        table.add_row(key, escape(str(value)))
    console.print(table)


@assets_app.command("search")
@reports_errors
def search(
    text: Annotated[str, typer.Argument(help="a description, e.g. 'a white ceramic mug'")],
    k: Annotated[int, typer.Option("-k", help="how many matches", min=1)] = 5,
    as_json: Annotated[bool, typer.Option("--json")] = False,
    embedding: Annotated[bool, typer.Option("--embedding", help="use the sentence-embedding retriever")] = False,
    library: LibraryOpt = None,
) -> None:
    """Rank assets for a description; shows what `resolve` would pick."""
    catalogue = _catalogue(library)
    if embedding:
        catalogue.retrieval = "embedding"
    hits = catalogue.hits(text, k)
    resolved = catalogue.resolve(text)
    if as_json:
        payload = {
            "query": text,
            "matches": [
                {
                    "id": h.asset_id,
                    "category": catalogue.entry(h.asset_id).category,
                    "score": round(h.score, 4),
                    "confidence": round(h.confidence, 4),
                }
                for h in hits
            ],
            "resolved": {
                "id": resolved.id,
                "category": resolved.category,
                "generated": resolved.generated,
                "size": list(resolved.size),
            },
        }
        sys.stdout.write(json.dumps(payload, indent=1) + "\n")
        return
    table = Table("rank", "id", "category", "score", "confidence")
    for rank, h in enumerate(hits, 1):
        table.add_row(
            str(rank), h.asset_id, catalogue.entry(h.asset_id).category, f"{h.score:.3f}", f"{h.confidence:.2f}"
        )
    console.print(table)
    tag = " (generated)" if resolved.generated else ""
    console.print(f"resolves to {resolved.id}{tag}: {escape(resolved.category)}, {_fmt_size(resolved.size)}")


@assets_app.command("import")
@reports_errors
def import_library(
    folder: Annotated[Path, typer.Argument(help="library folder with library.yaml")],
    as_json: Annotated[bool, typer.Option("--json", help="print the summary as JSON")] = False,
    workers: Annotated[int, typer.Option("--workers", "-w", help="entries imported at once", min=1, max=64)] = 2,
    register: Annotated[
        bool,
        typer.Option(
            "--register/--no-register", help="remember the library in the config file, so every command uses it"
        ),
    ] = True,
) -> None:
    """Ingest a user library (normalise, check, decompose, cache), report each entry and remember the library.

    Exit code 0 if every entry imported, 1 if some failed (each listed with its reason),
    2 if the library itself is unreadable.
    """
    from physcensis.assets.cache import AssetCache
    from physcensis.assets.library import load_library, read_library_spec

    total = len(read_library_spec(folder).assets)  # an unreadable library is a LibraryError: one line, exit 2
    with _import_progress(total) as progress:
        result = load_library(folder, cache=AssetCache(), workers=workers, progress=progress)
    failures = [_failure(err) for err in result.errors]
    clashes = _id_clashes(folder, result.assets)
    failures += clashes.values()
    imported = [asset for asset in result.assets if asset.id not in clashes]
    registered = _register(folder) if register and imported else None
    if as_json:
        payload = {
            "folder": str(folder),
            "imported": [_imported(asset) for asset in imported],
            "failed": failures,
            "registered_in": registered,
        }
        sys.stdout.write(json.dumps(payload, indent=1) + "\n")
    else:
        _print_import_summary(imported, failures)
        if registered:
            console.print(
                f"every command now uses {escape(str(folder))} (listed in {escape(registered)}; "
                "`physcensis assets forget` removes it)",
                highlight=False,
            )
    raise finish(not failures)


def _id_clashes(folder: Path, assets: list[Asset]) -> dict[str, dict[str, str]]:
    """The imported assets whose id a built-in or another library in use already has (the catalogue would skip
    them), each as a failure naming who has the id."""
    catalogue = with_libraries(None)
    here = folder.resolve()
    clashes = {}
    for asset in assets:
        if asset.id not in catalogue:
            continue
        entry = catalogue.entry(asset.id)
        if entry.builtin:
            owner = "a built-in asset"
        elif Path(entry.source).resolve().is_relative_to(here):
            continue  # this library itself, imported before
        else:
            owner = f"{entry.source}"
        reason = f"id {asset.id!r} is already used by {owner}; give this entry another id"
        clashes[asset.id] = {"entry": f"{asset.source} ({asset.id})", "reason": reason}
    return clashes


def _register(folder: Path) -> str | None:
    """Add the library to the config file; the config's path, or None (with a warning) when it cannot be written."""
    from physcensis.assets.libraries import config_path, register_library

    try:
        register_library(folder)
    except AssetError as exc:  # the import itself worked: a config that cannot be written is a warning
        print_warning(f"{exc}; use --library {folder} or PHYSCENSIS_LIBRARY to use the library")
        return None
    return str(config_path())


@assets_app.command("forget")
@reports_errors
def forget(folder: Annotated[Path, typer.Argument(help="a library folder that `assets import` remembered")]) -> None:
    """Stop using a library by default (remove it from the config file); its files are left alone."""
    from physcensis.assets.libraries import config_path, configured_libraries, forget_library

    if not forget_library(folder):
        listed = ", ".join(str(p) for p in configured_libraries()) or "none"
        raise fail(f"{folder} is not in {config_path()} (libraries in use: {listed})")
    console.print(f"{escape(str(folder))} is no longer used by default", highlight=False)


@contextmanager
def _import_progress(total: int) -> Iterator[Callable[[str, object], None] | None]:
    """A progress bar on stderr while entries import, only when stderr is a terminal (stdout stays clean)."""
    if not sys.stderr.isatty() or total < 2:
        yield None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    columns = (TextColumn("importing"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    with Progress(*columns, console=err_console, transient=True) as bar:
        task = bar.add_task("import", total=total)
        yield lambda _label, _outcome: bar.advance(task)


def _failure(err: AssetError) -> dict[str, str]:
    entry, reason = getattr(err, "entry", None), getattr(err, "reason", None)
    return {"entry": entry, "reason": reason} if entry and reason else {"entry": "", "reason": str(err)}


def _imported(asset: Asset) -> dict[str, Any]:
    return {
        "id": asset.id,
        "category": asset.category,
        "size": list(asset.size),
        "mass": asset.mass,
        "collision_parts": len(asset.collision),
        "guessed": sorted(asset.guessed),
        "pose": asset.pose,
        "rests": asset.rests,
        "source": asset.source,
    }


def _print_import_summary(assets: list[Asset], failures: list[dict[str, str]]) -> None:
    """One line per entry (ok or failed with its reason), then the counts."""
    for asset in assets:
        flags = f" guessed: {', '.join(sorted(asset.guessed))}" if asset.guessed else ""
        flags += f" up: {asset.pose}" if asset.pose else ""
        flags += "" if asset.rests else " (rests in no pose: collision pressed flat where it lies)"
        console.print(
            f"ok  {asset.id}: {asset.category}, {_fmt_size(asset.size)}, {len(asset.collision)} convex parts{flags}",
            highlight=False,
            soft_wrap=True,
            markup=False,
        )
    for failure in failures:
        where = f"{failure['entry']}: " if failure["entry"] else ""
        console.print(f"failed  {where}{failure['reason']}", highlight=False, soft_wrap=True, markup=False)
    console.print(f"{len(assets)} assets imported, {len(failures)} failed", highlight=False)


@assets_app.command("gallery")
@reports_errors
def gallery(
    out: Annotated[Path, typer.Option("--out", "-o", help="PNG file to write")],
    category: Annotated[
        list[str] | None, typer.Option("--category", "-c", help="only these categories (repeatable)")
    ] = None,
    cols: Annotated[int, typer.Option(help="tiles per row", min=1)] = 16,
    tile: Annotated[int, typer.Option(help="tile size in pixels", min=64, max=1024)] = 160,
    library: LibraryOpt = None,
    overwrite: Annotated[bool, typer.Option("--overwrite", help="replace an existing file that is not a PNG")] = False,
) -> None:
    """Render a contact sheet headless with MuJoCo: the assets of the --library folders when given (to look at
    what an import made), else the whole catalogue; -c narrows either to categories."""
    from physcensis.fileio import check_output_file
    from physcensis.imageio import PNG_MAGIC
    from physcensis.physics.contact_sheet import render_contact_sheet

    check_output_file(out, overwrite=overwrite, suffixes=[PNG_MAGIC])
    catalogue = _catalogue(library)
    folders = [folder.resolve() for folder in library or ()]
    ids = [
        e.id
        for e in catalogue.entries()
        if (not category or e.category in category)
        and (not folders or (not e.builtin and any(Path(e.source).resolve().is_relative_to(f) for f in folders)))
    ]
    if not ids:
        raise AssetError(f"no assets in categories {category}")
    path = render_contact_sheet([catalogue.get(i) for i in ids], out, cols=cols, tile=tile)
    console.print(f"wrote {escape(str(path))} ({len(ids)} assets)")
