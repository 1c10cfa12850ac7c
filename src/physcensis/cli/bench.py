"""`physcensis bench`: the paper's benchmarks."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, cast

import typer

from physcensis.cli.errors import err_console, fail, reports_errors
from physcensis.cli.options import console, output_dir

if TYPE_CHECKING:
    from physcensis.bench.clutter import Mode

bench_app = typer.Typer(help="The paper's benchmarks.", no_args_is_help=True)
CLUTTER_SCENE_NAME = re.compile(r"(no-stack|with-stack|with-skip)_\d{4,}")


@bench_app.command("clutter")
@reports_errors
def bench_clutter(
    mode: Annotated[str, typer.Option(help="no-stack, with-stack or with-skip")] = "with-stack",
    scenes: Annotated[int, typer.Option(min=1, help="number of seeded scenes")] = 10,
    seed: Annotated[int, typer.Option(help="seed of the first scene")] = 0,
    overhang: Annotated[
        bool, typer.Option(help="objects may stick out past the table edge if they rest stably")
    ] = False,
    as_json: Annotated[bool, typer.Option("--json", help="print the summary as JSON")] = False,
    out: Annotated[Path | None, typer.Option(help="save every scene's folder here")] = None,
    overwrite: Annotated[
        bool,
        typer.Option("--overwrite", help="save into a non-empty folder that holds other things (they are left alone)"),
    ] = False,
    patience: Annotated[
        int,
        typer.Option(min=1, help="stop after N failures in a row, skipping each failed object (1: the paper's rule)"),
    ] = 1,
    spot: Annotated[
        str,
        typer.Option(
            help="where PLACE-ANYWHERE puts each object: packed against the others and the edges (ours), or random, "
            "the predicate's own random spot among those that fit"
        ),
    ] = "packed",
    peer: Annotated[
        str | None,
        typer.Option(help="run the protocol with a peer instead (scene-synthesizer; needs `physcensis[peer]`)"),
    ] = None,
) -> None:
    """The clutter-count protocol: YCB dining objects placed with PLACE-ANYWHERE until one does not fit."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from physcensis.bench import clutter

    if mode not in clutter.MODES:
        raise fail(f"unknown mode {mode!r}; choose one of {', '.join(clutter.MODES)}")
    if spot not in clutter.PLACEMENTS:
        raise fail(f"unknown --spot {spot!r}; choose one of {', '.join(clutter.PLACEMENTS)}")
    if peer is not None:
        _peer_clutter(peer, mode, scenes, seed, patience=patience, overhang=overhang, as_json=as_json)
        return
    if out is not None:
        _clutter_folder(out, overwrite)
        for i in range(scenes):
            output_dir(out / clutter.scene_folder_name(mode, seed + i), overwrite=False)
    with Progress(
        TextColumn("[bold]clutter {task.fields[mode]}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("last: {task.fields[last]} objects"),
        TimeElapsedColumn(),
        console=err_console,
        disable=as_json,
    ) as progress:
        task = progress.add_task("scenes", total=scenes, mode=mode, last="-")
        summary = clutter.run(
            cast("Mode", mode),
            scenes,
            seed,
            out_dir=out,
            overhang=overhang,  # checked above
            patience=patience,
            placement=spot,
            progress=lambda i, r: progress.update(task, advance=1, last=str(r.placed)),
        )
    if as_json:
        typer.echo(json.dumps(summary, indent=2))
        return
    console.print(
        f"{mode}, {spot} spots{' (overhang allowed)' if overhang else ''}"
        f"{f', stop after {patience} failures in a row' if patience > 1 else ''}: {summary['mean_objects']:.2f} ± "
        f"{summary['std_objects']:.2f} objects over {scenes} scenes "
        f"(paper: {summary['paper'].get(mode, '-')}); {summary['mean_seconds_per_scene']:.1f} s per "
        f"scene; settle distance {summary['mean_settle_distance_m'] * 1000:.3f} mm"
    )


def _peer_clutter(
    peer: str, mode: str, scenes: int, seed: int, *, patience: int, overhang: bool, as_json: bool
) -> None:
    """`bench clutter --peer`: the same protocol run by a peer, every scene re-simulated under MuJoCo's defaults."""
    from physcensis.bench import peer_scene_synthesizer as peers

    if peer not in peers.PEERS:
        raise fail(f"unknown peer {peer!r}; choose one of {', '.join(peers.PEERS)}")
    if mode not in peers.PEER_MODES:
        raise fail(f"the peer runs --mode {' or '.join(peers.PEER_MODES)}, not {mode}")
    try:
        peers.load_scene_synthesizer()
    except peers.PeerUnavailable as exc:
        raise fail(str(exc)) from exc
    summary = peers.run_peer(mode, scenes, seed, patience=patience, overhang=overhang)
    if as_json:
        typer.echo(json.dumps(summary, indent=2))
        return
    defaults = summary["mujoco_default"]
    console.print(
        f"{summary['peer']} {mode}{' (overhang allowed)' if overhang else ''}: {summary['mean_objects']:.2f} ± "
        f"{summary['std_objects']:.2f} objects placed over {scenes} scenes, {defaults['mean_resting']:.2f} still "
        f"resting under MuJoCo's defaults; settle distance {defaults['mean_settle_distance_m'] * 1000:.3f} mm; "
        f"{summary['mean_seconds_per_scene']:.1f} s per scene"
    )


def _clutter_folder(out: Path, overwrite: bool) -> None:
    """The folder of clutter scenes: new, empty or holding only clutter scenes, unless --overwrite."""
    from physcensis.fileio import owned_entries
    from physcensis.gallery import INDEX_NAME

    if out.is_symlink() or (out.exists() and not out.is_dir()):
        raise fail(f"{out}: is {'a symbolic link' if out.is_symlink() else 'not a folder'}; give a folder")
    if not out.is_dir() or overwrite:
        return
    foreign = [
        e.name
        for e in out.iterdir()
        if not (CLUTTER_SCENE_NAME.fullmatch(e.name) and e.is_dir() and not e.is_symlink() and owned_entries(e))
        and not (e.name == INDEX_NAME and e.is_file() and not e.is_symlink())  # `physcensis report` of the scenes
    ]
    if foreign:
        raise fail(
            f"{out}: holds other things than clutter scenes ({', '.join(sorted(foreign)[:3])}); give an "
            "empty or new folder, or --overwrite to add the scenes beside them"
        )
