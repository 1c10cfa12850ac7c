"""The predicate language: registry, parser and checker."""

from __future__ import annotations

from physcensis.program.checker import DEFAULT_MAX_OBJECTS, CheckReport, check_program
from physcensis.program.model import Declaration, ItemCount, Problem, Program, Relation
from physcensis.program.parser import load_program, parse_program
from physcensis.program.registry import PREDICATES, Axis, Effect, PlacementKind, PredicateSpec, Solver, lookup

__all__ = [
    "DEFAULT_MAX_OBJECTS",
    "PREDICATES",
    "Axis",
    "CheckReport",
    "Declaration",
    "Effect",
    "ItemCount",
    "PlacementKind",
    "PredicateSpec",
    "Problem",
    "Program",
    "Relation",
    "Solver",
    "check_program",
    "load_program",
    "lookup",
    "parse_program",
]
