from __future__ import annotations

import ast
import json
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import typer
from typer.testing import CliRunner, Result

import physcensis.cli as cli_package
from physcensis.assets.cache import CACHE_ENV
from physcensis.cli import app
from physcensis.cli.app import OneLineErrorsGroup
from physcensis.cli.errors import EXIT_CODE_MEANINGS, ExitCode, fail, reports_errors
from physcensis.program.registry import PREDICATES
from physcensis.scene import Scene, Support, save_scene

from .conftest import EXAMPLES
from .scenes import placed_object

runner = CliRunner()


def test_check_clean_program_exits_zero() -> None:
    result = runner.invoke(app, ["check", str(EXAMPLES / "dining_4.json")])
    assert result.exit_code == 0, result.output
    assert "0 errors" in " ".join(result.output.split())  # the line wraps where the checkout's path is long


def test_check_json_lists_problems_and_exits_one(tmp_path: Path) -> None:
    path = tmp_path / "bad.json"
    path.write_text('[["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]]')
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 1
    rows = json.loads(result.stdout)
    assert rows == [
        {"index": 2, "object": "cup_0", "severity": "error", "rule": "place-on-root", "message": rows[0]["message"]}
    ]
    assert set(rows[0]) >= {"index", "object", "severity", "message"}


def test_check_unreadable_file_exits_two_with_one_line(tmp_path: Path) -> None:
    result = runner.invoke(app, ["check", str(tmp_path / "nope.json")])
    assert result.exit_code == 2
    assert "cannot read" in " ".join(result.output.split()) and "Traceback" not in result.output
    garbage = tmp_path / "garbage.txt"
    garbage.write_bytes(b"\xff\xfe\x00 not utf8")
    assert runner.invoke(app, ["check", str(garbage)]).exit_code == 2


def test_check_reads_stdin_and_support_option() -> None:
    text = '[["a","a cup"],["a","PLACE-ON-BASE","root",{"x":2,"y":0}],["a","FACING-FRONT","root"]]'
    assert runner.invoke(app, ["check", "-"], input=text).exit_code == 0
    result = runner.invoke(app, ["check", "-", "--support", "table:1x1"], input=text)
    assert result.exit_code == 1 and "off the support" in result.output
    bad_support = runner.invoke(app, ["check", "-", "--support", "table:one"], input=text)
    assert bad_support.exit_code == 2


def test_predicates_json_lists_the_registry() -> None:
    result = runner.invoke(app, ["predicates", "--json"])
    assert result.exit_code == 0
    names = [row["name"] for row in json.loads(result.stdout)]
    assert names == list(PREDICATES)


@pytest.mark.long  # a command-line run in its own process
def test_console_script_runs_in_a_real_process() -> None:
    exe = Path(sys.executable).with_name("physcensis")
    done = subprocess.run(
        [str(exe), "check", str(EXAMPLES / "desk_llm_style.txt")], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    missing = subprocess.run([str(exe), "check", "/no/such/file"], capture_output=True, text=True, timeout=120)
    assert missing.returncode == 2
    assert "Traceback" not in missing.stderr and len(missing.stderr.strip().splitlines()) == 1


def test_solve_writes_a_scene_folder(tmp_path: Path) -> None:
    out = tmp_path / "dining"
    result = runner.invoke(app, ["solve", str(EXAMPLES / "dining_4.json"), "--out", str(out), "--no-physics"])
    assert result.exit_code == 0, result.output
    assert {p.name for p in out.iterdir()} == {"scene.json", "report.json", "layout.png", ".physcensis.json"}
    assert "placed 16" in result.output


def test_solve_prints_a_value_asked_for_that_the_scene_does_not_hold(tmp_path: Path) -> None:
    # A 16 cm deep book cannot stand with its centre 28 cm off the middle of a 60 cm deep table.
    program = {
        "support": {"kind": "table", "size": [0.8, 0.6]},
        "program": [
            ["book_0", "a hardcover book lying flat"],
            ["book_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": -0.28}],
            ["book_0", "FACING-FRONT", "root", {}],
        ],
    }
    source = tmp_path / "book.json"
    source.write_text(json.dumps(program))
    result = runner.invoke(app, ["solve", str(source), "--out", str(tmp_path / "out"), "--no-physics"])
    assert "not as asked: book_0" in result.output and "y -0.28 was asked for" in result.output, result.output


def test_generate_writes_a_scene_with_failed_objects_and_exits_one(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The exit code says what `--help` says: 1 when some objects failed, though the scene is written (it exited 0)."""
    import physcensis.api
    from physcensis.agent.loop import GenerateResult
    from physcensis.api import Generated
    from physcensis.solver.pipeline import solve

    program = [
        ["c_0", "a serving tray"],
        ["c_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}],
        ["c_0", "FACING-FRONT", "root", {}],
        [[["wine bottle", 1]], "PLACE-IN", "c_0", {}],  # a tray has no opening: the bottle fails
    ]
    solution = solve(program, support=Support(kind="table", size=(1.0, 0.8)), seed=0)
    assert [o.status for o in solution.scene.objects] == ["placed", "failed"]

    def fake_generate(prompt: str, **kwargs: object) -> Generated:
        return Generated(GenerateResult(solution, rounds=1), prompt, solution.scene.support)

    monkeypatch.setattr(physcensis.api, "generate", fake_generate)
    out = tmp_path / "tray"
    result = runner.invoke(app, ["generate", "a bottle in a tray", "--out", str(out), "--export", "none"])
    assert result.exit_code == ExitCode.PROBLEMS, result.output
    assert "failed 1" in " ".join(result.output.split())
    assert json.loads((out / "scene.json").read_text())["objects"][1]["status"] == "failed"


def test_solve_with_program_errors_exits_one_and_writes_nothing(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text('[["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]]')
    result = runner.invoke(app, ["solve", str(bad), "--out", str(tmp_path / "out"), "--no-physics"])
    assert result.exit_code == 1 and "place" in result.output.lower()
    assert not (tmp_path / "out").exists()


# -- one error path, one set of exit codes ------------------------------------------------------------------------
CLI_PACKAGE = Path(cli_package.__file__).parent
EXIT_CALLS = {"Exit", "exit", "SystemExit"}  # typer.Exit, sys.exit, raise SystemExit


def _cli_modules() -> list[tuple[str, ast.Module]]:
    modules = [(path.name, ast.parse(path.read_text(), str(path))) for path in sorted(CLI_PACKAGE.glob("*.py"))]
    assert {"errors.py", "app.py", "scenes.py"} <= {name for name, _ in modules}
    return modules


def _called_name(call: ast.Call) -> str | None:
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else func.id if isinstance(func, ast.Name) else None


def test_only_the_error_module_makes_an_error_console_or_exits_with_a_number() -> None:
    for name, tree in _cli_modules():
        for call in (node for node in ast.walk(tree) if isinstance(node, ast.Call)):
            where = f"cli/{name}:{call.lineno}"
            if _called_name(call) == "Console" and name != "errors.py":
                assert not any(k.arg == "stderr" for k in call.keywords), f"{where}: a second error console"
            if _called_name(call) in EXIT_CALLS:
                numbers = [
                    n
                    for arg in call.args
                    for n in ast.walk(arg)
                    if isinstance(n, ast.Constant) and isinstance(n.value, int)
                ]
                assert not numbers, f"{where}: exit with a literal number instead of an ExitCode"


def _commands(typer_app: typer.Typer, prefix: str = "") -> Iterator[tuple[str, Callable[..., Any]]]:
    for info in typer_app.registered_commands:
        assert info.callback is not None
        yield f"{prefix}{info.name or info.callback.__name__}", info.callback
    for group in typer_app.registered_groups:
        assert group.typer_instance is not None
        yield from _commands(group.typer_instance, f"{prefix}{group.name} ")


def test_every_command_turns_a_physcensis_error_into_one_line() -> None:
    wrapper = reports_errors(lambda: None).__code__  # the code of every function `reports_errors` returns
    commands = dict(_commands(app))
    assert {"check", "solve", "render", "stability", "eval settle", "assets import", "bench clutter"} <= set(commands)
    assert [name for name, callback in commands.items() if callback.__code__ is not wrapper] == []


def test_exit_codes_are_documented_in_the_help() -> None:
    result = runner.invoke(app, ["--help"])
    assert result.exit_code == 0
    text = " ".join(result.output.split())  # the epilog as one line, however the terminal wrapped it
    for code in ExitCode:
        assert f"{int(code)} {EXIT_CODE_MEANINGS[code]}" in text


def _one_error_line(result: Result) -> str:
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.output
    assert "Traceback" not in result.output
    return lines[0]


def test_an_unreadable_input_is_exit_2_and_one_line_from_every_command(tmp_path: Path) -> None:
    missing = tmp_path / "no_such.json"
    commands = [
        ["check", str(missing)],
        ["solve", str(missing), "--out", str(tmp_path / "solved")],
        ["render", str(missing), "--out", str(tmp_path / "picture.png")],
        ["export", str(missing), "--to", "mjcf", "--out", str(tmp_path / "exported")],
        ["eval", "settle", str(missing)],
        ["stability", str(missing)],
        ["assets", "import", str(tmp_path / "no_such_library")],
        ["batch", str(tmp_path / "no_such_prompts.txt"), "--out", str(tmp_path / "batch")],
    ]
    for args in commands:
        result = runner.invoke(app, args)
        assert result.exit_code == ExitCode.USAGE == 2, (args, result.output)
        assert "no_such" in _one_error_line(result), args
    assert sorted(p.name for p in tmp_path.iterdir()) == []  # nothing was written for any of them


def test_a_bad_argument_is_exit_2_from_every_command(tmp_path: Path) -> None:
    scene = save_scene(
        Scene(
            support=Support(kind="table", size=(0.8, 0.6)), objects=[placed_object("mug_0", "mug_white", 0.0, 0.0, 0.0)]
        ),
        tmp_path / "scene.json",
    )
    commands = [
        (["stability", str(scene), "--object", "nope"], "no placed object 'nope'"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--view", "sideways"], "unknown view"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--size", "big"], "must look like 960x720"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--elevation", "120"], "--elevation 120"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--fov", "0"], "--fov 0"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--distance", "-1"], "--distance -1"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--azimuth", "nan"], "--azimuth nan"),
        (["render", str(scene), "--out", str(tmp_path / "p.png"), "--view", "all", "--azimuth", "10"], "--view all"),
        (["bench", "clutter", "--mode", "tall-stack"], "unknown mode"),
        (["assets", "show", "no_such_asset"], "no asset with id"),
        (["export", str(scene), "--to", "none", "--out", str(tmp_path / "x")], "nothing to export"),
        (["generate", "a mug", "--variety", "lots", "--out", str(tmp_path / "g")], "--variety"),
        (["batch", str(scene), "--variety", "max", "--out", str(tmp_path / "b")], "--variety"),
    ]
    for args, message in commands:
        result = runner.invoke(app, args)
        assert result.exit_code == ExitCode.USAGE, (args, result.output)
        assert message in _one_error_line(result), args


def test_a_refused_output_is_exit_2_from_every_command(tmp_path: Path) -> None:
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("keep")
    scene = save_scene(
        Scene(
            support=Support(kind="table", size=(0.8, 0.6)), objects=[placed_object("mug_0", "mug_white", 0.0, 0.0, 0.0)]
        ),
        tmp_path / "scene.json",
    )
    commands = [
        ["solve", str(EXAMPLES / "dining_4.json"), "--out", str(foreign), "--no-physics"],
        ["export", str(scene), "--to", "mjcf", "--out", str(foreign)],
        ["render", str(scene), "--out", str(foreign / "notes.txt")],
        ["assets", "gallery", "--out", str(foreign / "notes.txt")],
    ]
    for args in commands:
        result = runner.invoke(app, args)
        assert result.exit_code == ExitCode.USAGE, (args, result.output)
        _one_error_line(result)
    assert [p.name for p in foreign.iterdir()] == ["notes.txt"] and (foreign / "notes.txt").read_text() == "keep"


def test_problems_in_what_was_read_are_exit_1_from_every_command(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(CACHE_ENV, str(tmp_path / "cache"))  # the import caches nothing in the user's cache
    bad_program = tmp_path / "bad.json"
    bad_program.write_text('[["cup_0", "a cup"], ["cup_0", "PLACE-ON", "root", {}]]')
    library = tmp_path / "library"
    library.mkdir()
    (library / "library.yaml").write_text('assets: [{file: "nope.obj", category: "toy block"}]')
    commands = [
        ["check", str(bad_program)],
        ["solve", str(bad_program), "--out", str(tmp_path / "out"), "--no-physics"],
        ["assets", "import", str(library)],
    ]
    for args in commands:
        result = runner.invoke(app, args)
        assert result.exit_code == ExitCode.PROBLEMS == 1, (args, result.output)
        assert "Traceback" not in result.output


def test_fail_prints_the_message_as_text_on_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    exit_ = fail("a [bold]file[/bold] named [red]x", ExitCode.PROBLEMS)
    assert exit_.exit_code == 1
    assert capsys.readouterr().err == "error: a [bold]file[/bold] named [red]x\n"


# -- a bad invocation is one line too, through the console entry point ---------------------------------------------
BAD_INVOCATIONS = [  # (arguments, what the line must name)
    (["solve", "p.json", "--out", "o", "--export", "bogus"], "'--export'"),
    (["solve", "p.json", "--out", "o", "--support", "nonsense"], "'--support'"),
    (["solve"], "'file'"),
    (["solve", "p.json", "--ot", "o"], "--ot"),
    (["generate", "a cup", "--rounds", "-3"], "'--rounds'"),
    (["generate", "a cup", "--llm-timeout", "-1"], "'--llm-timeout'"),
    (["stability", "scene.json", "--samples", "-5"], "'--samples'"),
    (["eval", "settle", "scene.json", "--engine", "bogus"], "'--engine'"),
    (["eval", "settle", "scene.json", "--seconds", "0"], "'--seconds'"),
    (["eval", "bogus"], "'bogus'"),
    (["predicates", "--bogus"], "--bogus"),
    (["export", "scene.json"], "'--to'"),
    (["export", "scene.json", "--to", "mjcf"], "'--out'"),
    (["render", "scene.json", "--out", "p.png", "extra"], "(extra)"),
    (["bogus"], "'bogus'"),
]


def _run_main(
    args: list[str], monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> tuple[int, str, str]:
    """The exit code, stdout and stderr of `physcensis ARGS` run by the console entry point (`physcensis.cli:main`),
    where the standalone mode (who prints click's errors) is decided."""
    monkeypatch.setattr(sys, "argv", ["physcensis", *args])
    with pytest.raises(SystemExit) as exited:
        cli_package.main()
    code = exited.value.code
    assert isinstance(code, int), code
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.mark.parametrize(("args", "names"), BAD_INVOCATIONS, ids=[" ".join(a) for a, _ in BAD_INVOCATIONS])
def test_a_bad_invocation_is_one_line_naming_what_is_wrong_and_exit_2(
    args: list[str], names: str, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = _run_main(args, monkeypatch, capsys)
    assert code == ExitCode.USAGE and out == ""
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert names in lines[0] and lines[0].endswith("--help)"), lines[0]


def test_a_bad_value_is_described_in_clicks_words(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    _, _, err = _run_main(["solve", "p.json", "--out", "o", "--export", "bogus"], monkeypatch, capsys)
    assert err.startswith("error: invalid value for '--export': unknown export format 'bogus'")
    assert err.rstrip().endswith("(see physcensis solve --help)")


@pytest.mark.parametrize("args", [["--help"], ["solve", "--help"], ["eval", "settle", "--help"]])
def test_help_still_exits_0(
    args: list[str], monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = _run_main(args, monkeypatch, capsys)
    assert code == ExitCode.OK and err == ""
    assert f"Usage: physcensis {' '.join(args[:-1])}".rstrip() in " ".join(out.split())


def test_no_arguments_print_the_help_and_no_error(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = _run_main([], monkeypatch, capsys)
    assert code == ExitCode.USAGE and err == ""
    assert "Usage: physcensis [OPTIONS] COMMAND" in out


def test_interrupts_and_explicit_exits_keep_their_codes() -> None:
    stub = typer.Typer(cls=OneLineErrorsGroup)

    @stub.command()
    def interrupted() -> None:
        raise KeyboardInterrupt

    @stub.command()
    def exits(code: int) -> None:
        raise typer.Exit(code)

    assert runner.invoke(stub, ["interrupted"]).exit_code == ExitCode.INTERRUPTED
    assert runner.invoke(stub, ["exits", "3"]).exit_code == 3
    assert runner.invoke(stub, ["exits", "0"]).exit_code == ExitCode.OK


def test_a_folder_without_a_scene_is_the_same_error_from_every_command(tmp_path: Path) -> None:
    empty = tmp_path / "empty"
    empty.mkdir()
    commands = [
        ["render", str(empty), "--out", str(tmp_path / "p.png")],
        ["export", str(empty), "--to", "mjcf", "--out", str(tmp_path / "exported")],
        ["stability", str(empty)],
        ["eval", "settle", str(empty)],
    ]
    lines = [_one_error_line(runner.invoke(app, args)) for args in commands]
    assert lines[:3] == [f"error: {empty}: no scene.json in this folder"] * 3
    assert lines[3] == f"error: {empty}: no scene.json in this folder or below it"  # settle also searches below
    assert [p.name for p in tmp_path.iterdir()] == ["empty"]


def test_render_views_angles_and_a_sheet_of_every_view(tmp_path: Path) -> None:
    """`render` takes named views (side ones too), angles, a distance and a field of view, and `--view all` draws
    one framed tile per view."""
    from PIL import Image

    from physcensis.physics.render import VIEWS

    def read_png(path: Path) -> np.ndarray:
        with Image.open(path) as image:
            return np.asarray(image.convert("RGB"))

    scene = save_scene(
        Scene(
            support=Support(kind="table", size=(0.8, 0.6)), objects=[placed_object("mug_0", "mug_white", 0.0, 0.0, 0.0)]
        ),
        tmp_path / "scene.json",
    )
    pictures = {}
    for name, args in {
        "default": [],
        "side": ["--view", "side", "--size", "320x240"],
        "close": ["--view", "side", "--size", "320x240", "--distance", "0.4", "--fov", "30"],
        "low": ["--azimuth", "200", "--elevation", "-5", "--size", "320x240"],
    }.items():
        out = tmp_path / f"{name}.png"
        result = runner.invoke(app, ["render", str(scene), "--out", str(out), *args])
        assert result.exit_code == 0, result.output
        pictures[name] = read_png(out)
    assert max(pictures["default"].shape[:2]) == 960  # shaped to the scene
    assert pictures["side"].shape[:2] == (240, 320)
    assert not np.array_equal(pictures["side"], pictures["close"]) and not np.array_equal(
        pictures["side"], pictures["low"]
    )
    sheet = tmp_path / "all.png"
    result = runner.invoke(app, ["render", str(scene), "--out", str(sheet), "--view", "all", "--size", "200x150"])
    assert result.exit_code == 0, result.output
    columns = min(4, len(VIEWS))
    assert read_png(sheet).shape[:2] == (150 * -(-len(VIEWS) // columns), 200 * columns)
