"""Scene folders for the robot tests: a program in this folder solved and written with its MJCF export."""

from __future__ import annotations

from pathlib import Path

from physcensis.output import write_solution
from physcensis.program.parser import load_program
from physcensis.solver.pipeline import solve

HERE = Path(__file__).parent


def solved_folder(program_name: str, out: Path) -> Path:
    """`program_name` (a file beside this one) solved with seed 0 into the scene folder `out`."""
    solution = solve(load_program(HERE / program_name), seed=0)
    assert solution.ok, solution.report()
    write_solution(solution, out, exports=("mjcf",))
    return out
