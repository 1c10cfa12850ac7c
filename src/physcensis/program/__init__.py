"""The predicate language: registry, parser and checker."""

from __future__ import annotations

from physcensis.program.checker import CheckReport, check_program
from physcensis.program.model import Declaration, ItemCount, Problem, Program, Relation
from physcensis.program.parser import load_program, parse_program
from physcensis.program.registry import PREDICATES, Axis, Kind, PredicateSpec, lookup

__all__ = [
    "PREDICATES",
    "Axis",
    "CheckReport",
    "Declaration",
    "ItemCount",
    "Kind",
    "PredicateSpec",
    "Problem",
    "Program",
    "Relation",
    "check_program",
    "load_program",
    "lookup",
    "parse_program",
]
