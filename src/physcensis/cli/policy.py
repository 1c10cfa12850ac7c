"""`physcensis policy train|eval|experiment`: behaviour cloning on recorded demonstrations, rolled out in unseen
scenes (the `policy` extra: torch and robomimic, imported only when a command runs)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn
from rich.table import Table

from physcensis.cli.errors import ExitCode, fail, finish, reports_errors
from physcensis.cli.options import console, output_dir

policy_app = typer.Typer(
    help="Train a policy on demonstrations (robomimic BC) and evaluate it in unseen scenes.", no_args_is_help=True
)

OverwriteOption = Annotated[bool, typer.Option("--overwrite", help="write into a folder that holds other files")]


def _progress() -> Progress:
    return Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeRemainingColumn(),
        console=console,
        transient=True,
    )


@policy_app.command("train")
@reports_errors
def policy_train(
    dataset: Annotated[Path, typer.Argument(help="the demos.hdf5 that `physcensis demo` or `demo-batch` wrote")],
    out: Annotated[Path, typer.Option("--out", "-o", help="folder for policy.pth and train.json")],
    steps: Annotated[int, typer.Option(min=1, help="gradient steps")] = 5000,
    batch_size: Annotated[int, typer.Option("--batch-size", min=1, help="samples per step")] = 64,
    seed: Annotated[int, typer.Option(min=0, help="seeds the network, the batches and everything else drawn")] = 0,
    rnn: Annotated[
        bool, typer.Option("--rnn", help="BC-RNN (an LSTM over 10 steps) instead of BC with an MLP")
    ] = False,
    max_episodes: Annotated[
        int | None, typer.Option("--max-episodes", min=1, help="learn from the first K successful episodes only")
    ] = None,
    overwrite: OverwriteOption = False,
) -> None:
    """Learn a state-based policy from the successful episodes of a demonstration dataset."""
    from physcensis.policy import TrainSettings, train

    settings = TrainSettings(
        steps=steps,
        batch_size=batch_size,
        seed=seed,
        rnn=rnn,
        hidden=(400,) if rnn else TrainSettings.hidden,
        max_episodes=max_episodes,
    )
    output_dir(out, overwrite)
    try:
        with _progress() as progress:
            bar = progress.add_task("training", total=steps)
            result = train(dataset, out, settings, lambda done, _: progress.update(bar, completed=done), overwrite=True)
    except KeyboardInterrupt:
        raise fail("stopped; nothing was written", ExitCode.INTERRUPTED) from None
    console.print(
        f"trained on {result.episodes} episodes ({result.samples} steps) for {result.steps} steps in "
        f"{result.seconds:.0f} s; loss {result.first_loss:.4f} -> {result.final_loss:.4f}"
    )
    console.print(f"wrote {escape(str(result.policy_path))}", highlight=False)


@policy_app.command("eval")
@reports_errors
def policy_eval(
    policy: Annotated[Path, typer.Argument(help="the folder `physcensis policy train` wrote")],
    scenes: Annotated[Path, typer.Option("--scenes", help="a scene folder or a folder of scene folders")],
    task: Annotated[str, typer.Option("--task", help="what to do, in each scene's own objects or in words")] = (
        "pick up the leftmost cup and place it on the rightmost plate"
    ),
    episodes: Annotated[
        int | None, typer.Option("--episodes", min=1, help="rollouts (default: one per scene folder)")
    ] = None,
    max_steps: Annotated[int, typer.Option("--max-steps", min=1, help="steps of 50 ms before giving up")] = 600,
    videos: Annotated[int, typer.Option("--videos", min=0, help="film the first K rollouts (MP4, 640x480)")] = 2,
    seed: Annotated[int, typer.Option(min=0, help="seed of the first rollout")] = 0,
    out: Annotated[Path | None, typer.Option("--out", "-o", help="folder for eval.json (default: POLICY/eval)")] = None,
    overwrite: OverwriteOption = False,
) -> None:
    """Roll a trained policy out in scenes and report reaching and placing with 95 % confidence intervals."""
    from physcensis.policy import EvalSettings, evaluate
    from physcensis.robot.env import scene_folders

    target = out if out is not None else policy / "eval"
    count = episodes if episodes is not None else len(scene_folders(scenes))
    output_dir(target, overwrite)
    settings = EvalSettings(task=task, episodes=count, max_steps=max_steps, seed=seed, videos=videos)
    try:
        with _progress() as progress:
            bar = progress.add_task("rollouts", total=count)
            result = evaluate(
                policy, scenes, target, settings, overwrite=True, on_episode=lambda _: progress.advance(bar)
            )
    except KeyboardInterrupt:
        raise fail("stopped; nothing was written", ExitCode.INTERRUPTED) from None
    table = Table("episode", "scene", "reached (step)", "placed", "steps")
    for k, episode in enumerate(result.episodes):
        reached = f"yes ({episode.reached_step})" if episode.reached else "no"
        table.add_row(str(k), escape(Path(episode.scene).name), reached, "yes" if episode.placed else "no",
                      str(episode.steps))  # fmt: skip
    console.print(table)
    for name, rate in (("reaching", result.reaching), ("placing", result.placing)):
        console.print(
            f"{name}: {rate.successes}/{rate.trials} ({rate.rate:.0%}; 95 % CI {rate.low:.0%}–{rate.high:.0%})"
        )
    console.print(f"wrote {escape(str(target / 'eval.json'))}", highlight=False)
    raise finish(True)


@policy_app.command("experiment")
@reports_errors
def policy_experiment(
    work: Annotated[Path, typer.Option("--work", help="scenes, demonstrations, policies, rollouts (resumable)")] = Path(
        "out/policy_variety"
    ),
    out: Annotated[Path, typer.Option("--out", "-o", help="the result JSON")] = Path(
        "bench/results/policy_variety.json"
    ),
    demos: Annotated[int, typer.Option("--demos", min=1, help="N: demonstrations per training set")] = 20,
    eval_scenes: Annotated[int, typer.Option("--eval-scenes", min=1, help="M: unseen scenes per prompt")] = 10,
    steps: Annotated[int, typer.Option(min=1, help="gradient steps of each training")] = 5000,
) -> None:
    """N demonstrations in N varied scenes against N in one scene: both policies on the same unseen scenes."""
    import json

    from physcensis.fileio import atomic_write_text
    from physcensis.policy import TrainSettings
    from physcensis.policy.experiment import ExperimentSettings, run, table

    settings = ExperimentSettings(demos=demos, eval_scenes=eval_scenes, training=TrainSettings(steps=steps))
    with console.status("the variety experiment…") as status:
        record = run(work, settings, log=lambda line: status.update(escape(line)))
    atomic_write_text(out, json.dumps(record, indent=2) + "\n")
    console.print(table(record))
    console.print(f"wrote {escape(str(out))}", highlight=False)
