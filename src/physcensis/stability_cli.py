"""`physcensis stability SCENE`: the probability that each object falls under small perturbations."""

from __future__ import annotations

import json as jsonlib
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from physcensis.errors import PhyscensisError

if TYPE_CHECKING:  # the command imports the physics only when it runs, so the CLI starts fast
    from physcensis.solve.stability import SceneStability

EXIT_UNKNOWN_OBJECT, EXIT_UNREADABLE = 1, 2


def stability(
    scene_path: Annotated[Path, typer.Argument(help="scene.json or a scene folder")],
    object_id: Annotated[str | None, typer.Option("--object", help="only this object")] = None,
    samples: Annotated[int, typer.Option("--samples", min=8, help="perturbed simulations per object")] = 128,
    as_json: Annotated[bool, typer.Option("--json", help="print JSON")] = False,
    seed: Annotated[int, typer.Option(help="random seed of the perturbations")] = 0,
) -> None:
    """p_fail of each placed object (or one): the kernel-weighted share of perturbed simulations in which it fell.
    The scene's p_fail is its most fragile object's."""
    from physcensis.scene import load_scene
    from physcensis.solve.stability import estimate_scene_stability

    errors = Console(stderr=True)
    try:
        scene = load_scene(scene_path)
    except PhyscensisError as exc:
        errors.print(f"[bold red]error:[/] {escape(str(exc))}", highlight=False, soft_wrap=True)
        raise typer.Exit(EXIT_UNREADABLE) from None
    placed = [o.id for o in scene.placed]
    if object_id is not None and object_id not in placed:
        known = ", ".join(placed) or "none"
        errors.print(f"[bold red]error:[/] {escape(f'{scene_path}: no placed object {object_id!r} (placed: {known})')}",
                     highlight=False, soft_wrap=True)
        raise typer.Exit(EXIT_UNKNOWN_OBJECT)
    result = estimate_scene_stability(scene, [object_id] if object_id else placed, samples, seed)
    if as_json:
        typer.echo(jsonlib.dumps({"scene": str(scene_path), "seed": seed} | result.to_dict(), indent=2))
        return
    _print_table(result)


def _print_table(result: SceneStability) -> None:
    console = Console()
    table = Table(show_header=True, header_style="bold")
    for column in ("object", "p_fail", "fell / samples", "effective samples", "time (s)"):
        table.add_column(column, justify="left" if column == "object" else "right")
    for e in result.objects.values():
        table.add_row(escape(e.object_id), f"{e.p_fail:.3f}", f"{e.fell} / {e.samples}", f"{e.effective_samples:.0f}",
                      f"{e.wall_s:.2f}")
    console.print(table)
    console.print(f"scene p_fail (most fragile object): {result.p_fail:.3f}; mean {result.mean_p_fail:.3f}")
