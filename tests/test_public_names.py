"""`physcensis.solve` and `physcensis.generate` are the real functions (their own signatures, for help() and type
checkers), yet `import physcensis` loads neither the solvers nor MuJoCo."""

from __future__ import annotations

import inspect
import subprocess
import sys

import pytest

import physcensis
import physcensis.api
import physcensis.solver.pipeline


def test_the_public_functions_are_the_real_ones_with_their_signatures() -> None:
    assert physcensis.solve is physcensis.solver.pipeline.solve
    assert physcensis.generate is physcensis.api.generate
    assert list(inspect.signature(physcensis.solve).parameters)[:4] == ["source", "support", "catalogue", "seed"]
    assert "settings" in inspect.signature(physcensis.generate).parameters
    from physcensis import generate, solve

    assert (solve, generate) == (physcensis.solve, physcensis.generate)
    assert {"solve", "generate"} <= set(dir(physcensis))


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no attribute 'sovle'"):
        physcensis.sovle  # type: ignore[attr-defined]  # noqa: B018 - mypy and Python both refuse the misspelling


@pytest.mark.slow
def test_importing_the_package_loads_no_solver_and_no_mujoco() -> None:
    code = (
        "import sys, physcensis\n"
        "loaded = [m for m in ('mujoco', 'physcensis.api', 'physcensis.solver.pipeline') if m in sys.modules]\n"
        "assert loaded == [], loaded\n"
        "assert callable(physcensis.solve) and 'physcensis.solver.pipeline' in sys.modules\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]


def test_the_command_line_loads_no_catalogue_mesh_library_or_engine_for_its_help() -> None:
    """`physcensis --help` costs its imports: the catalogue (trimesh, SciPy), MuJoCo and the OpenAI client are
    imported by the commands that use them, not by the command line itself."""
    heavy = ("physcensis.assets.catalogue", "trimesh", "scipy", "mujoco", "openai", "physcensis.api")
    code = (
        "import sys\n"
        "from physcensis.cli import app\n"
        f"loaded = [m for m in {heavy!r} if m in sys.modules]\n"
        "assert loaded == [], loaded\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
