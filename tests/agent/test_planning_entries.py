"""The order a plan's entries are written in: a program names only what it introduced earlier."""

from __future__ import annotations

from physcensis.agent.planning.entries import Plan
from physcensis.program.checker import check_program
from physcensis.program.parser import parse_program
from physcensis.scene import Support


def test_a_holder_placed_anywhere_comes_before_what_is_put_in_it() -> None:
    """A bowl of grapes the words gave no place of its own is PLACE-ANYWHERE (free), its grapes PLACE-IN (physical):
    the bowl's entries go first, the rest keep the paper's order (spatial, physical, free)."""
    plan = Plan()
    plan.anchors += [["plate_0", "a dinner plate"], ["plate_0", "PLACE-ON-BASE", "root", {"x": 0.0, "y": 0.0}]]
    plan.anchors += [["plate_0", "FACING-FRONT", "root", {}]]
    plan.physical += [["grapes_0", "a bunch of grapes"], [["grapes_0"], "PLACE-IN", "bowl_0", {}]]
    plan.physical += [["cup_0", "a cup"], ["cup_0", "PLACE-ON", "plate_0", {}]]
    plan.free += [["bowl_0", "a fruit bowl"], ["bowl_0", "PLACE-ANYWHERE", "root", {"stack": False}]]
    plan.free += [["vase_0", "a vase"], ["vase_0", "PLACE-ANYWHERE", "root", {"stack": False}]]
    program = plan.program()
    order = list(dict.fromkeys(e[0] if isinstance(e[0], str) else e[0][0] for e in program if len(e) > 2))
    assert order == ["plate_0", "bowl_0", "grapes_0", "cup_0", "vase_0"]
    report = check_program(parse_program(program), Support(kind="table", size=(0.8, 0.6)))
    assert report.ok, report.errors  # the paper's order is a preference: the bowl's early PLACE-ANYWHERE warns
