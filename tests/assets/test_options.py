"""Typed builder parameters: every builder declares them, every variant's options are checked when its
category is defined, and every declared parameter changes the shape the builder draws."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, replace
from typing import Any, Literal, get_args, get_origin, get_type_hints

import numpy as np
import pytest

from physcensis.assets.build import build_asset
from physcensis.assets.builtin import CATEGORY_DEFS
from physcensis.assets.errors import AssetError
from physcensis.assets.fallback import GENERIC
from physcensis.assets.gen.bottles import BottleShape, bottle, candle
from physcensis.assets.gen.utensils import fork
from physcensis.assets.spec import Builder, CategoryDef, Geometry, NoOptions, OptionError, Variant, builder, define

SIZE = (0.07, 0.07, 0.3)


def _bottles(options: dict[str, Any]) -> CategoryDef:
    return define(
        "bottle",
        "wine bottle",
        bottle,
        [V("plain", options=None), V("wine", options=options)],
        density=950.0,
        mass_limits=(0.2, 2.2),
    )


def V(name: str, options: dict[str, Any] | None) -> Variant:  # capital V: the tables' own spelling
    return Variant(name, f"a {name} thing", SIZE, options=options or {})


# -- options are checked when the table is defined ------------------------------------------------------------
def test_a_misspelt_key_fails_when_the_category_is_defined() -> None:
    with pytest.raises(OptionError) as err:
        _bottles({"nekc": 0.25})
    message = str(err.value)
    assert "category 'bottle' (wine bottle), variant 'wine'" in message
    assert "unknown option 'nekc' (did you mean 'neck'?)" in message
    assert message.endswith("valid options: neck, shoulder, neck_start, cap")
    assert "\n" not in message


@pytest.mark.parametrize(
    ("build", "options", "expected"),
    [
        (bottle, {"neck": "0.25"}, "option 'neck' is '0.25', expected a number"),
        (bottle, {"neck": True}, "option 'neck' is True, expected a number"),
        (bottle, {"cap": None}, "option 'cap' is None, expected a number"),
        (candle, {"style": "tapr"}, "option 'style' is 'tapr', expected one of 'pillar', 'taper', 'tealight', 'jar'"),
        (fork, {"tines": 3.0}, "option 'tines' is 3.0, expected an integer"),
    ],
)
def test_a_value_of_the_wrong_type_fails_when_the_category_is_defined(
    build: Builder[Any], options: dict[str, Any], expected: str
) -> None:
    with pytest.raises(OptionError, match="variant 'bad'") as err:
        define("thing", "thing", build, [V("bad", options)], density=900.0, mass_limits=(0.1, 1.0))
    assert expected in str(err.value)


def test_a_builder_without_options_names_none_as_valid() -> None:
    @builder(NoOptions)
    def plain(v: Variant, _: NoOptions) -> Geometry:
        return bottle.draw(v, BottleShape())

    with pytest.raises(OptionError, match=r"unknown option 'neck'; valid options: none$"):
        define("thing", "thing", plain, [V("bad", {"neck": 0.3})], density=900.0, mass_limits=(0.1, 1.0))


def test_good_options_become_the_typed_parameters() -> None:
    cat = _bottles({"neck": 1, "cap": 0.08})
    params = cat.build.parse(cat.variants[1].options, "here")
    assert params == BottleShape(neck=1.0, cap=0.08)
    assert isinstance(params.neck, float)  # an integer given for a number is stored as the number it means
    assert cat.build.parse({}, "here") == BottleShape()


def test_options_are_checked_again_when_a_variant_is_built_outside_its_table() -> None:
    cat = _bottles({"neck": 0.4})
    stray = replace(cat.variants[1], options={"shoulder": "high"})  # as `fallback.generate` derives variants
    with pytest.raises(AssetError, match="category 'bottle' .*variant 'wine': option 'shoulder' is 'high'"):
        build_asset(cat, stray)


def test_a_category_needs_a_registered_builder() -> None:
    def unregistered(v: Variant) -> Geometry:
        return bottle(v)

    with pytest.raises(TypeError, match=r"category 'thing' \(thing\): build must be a @builder"):
        define("thing", "thing", unregistered, [V("a", None)], density=900.0, mass_limits=(0.1, 1.0))  # type: ignore[arg-type]


def test_parameter_classes_are_frozen_with_defaults_and_supported_types() -> None:
    @dataclass
    class Mutable:
        neck: float = 0.3

    @dataclass(frozen=True)
    class NoDefault:
        neck: float

    @dataclass(frozen=True)
    class WrongDefault:
        neck: float = "thin"  # type: ignore[assignment]

    @dataclass(frozen=True)
    class Unsupported:
        neck: complex = 1j

    with pytest.raises(TypeError, match="Mutable: builder parameters must be a frozen dataclass"):
        builder(Mutable)
    with pytest.raises(TypeError, match="NoDefault.neck: every builder parameter needs a default"):
        builder(NoDefault)
    with pytest.raises(TypeError, match="WrongDefault.neck: default 'thin' is not a number"):
        builder(WrongDefault)
    with pytest.raises(TypeError, match="builder parameter type <class 'complex'> is not supported"):
        builder(Unsupported)


def test_builders_read_no_option_strings() -> None:
    assert not hasattr(Variant, "opt")


# -- every builder declares its parameters, and reads every one ----------------------------------------------
def _all_categories() -> list[CategoryDef]:
    generic = [replace(GENERIC, variants=(Variant("generic", "a thing", (0.1, 0.08, 0.06)),))]
    return [*CATEGORY_DEFS, *generic]


def _variants_by_builder() -> dict[str, tuple[Builder[Any], list[Variant]]]:
    table: dict[str, tuple[Builder[Any], list[Variant]]] = {}
    for cat in _all_categories():
        table.setdefault(cat.build.name, (cat.build, []))[1].extend(cat.variants)
    return table


def test_every_category_has_a_builder_with_a_frozen_parameter_class() -> None:
    for cat in _all_categories():
        assert isinstance(cat.build, Builder), cat.kind
        assert dataclasses.is_dataclass(cat.build.params), cat.kind
        with pytest.raises(dataclasses.FrozenInstanceError):
            cat.build.params().__setattr__("anything", 1)


def _other_values(hint: Any, value: Any) -> list[object]:
    """Values unlike `value` for a parameter of this type."""
    if get_origin(hint) is Literal:
        return [choice for choice in get_args(hint) if choice != value]
    if hint is bool:
        return [not value]
    if hint is int:
        return [value + 1]
    if value is None:  # an optional number left to its builder's own rule
        return [0.004]
    return [value * 1.1 if value else 0.05]


def _signature(geometry: Geometry) -> list[np.ndarray]:
    arrays = [np.asarray(mesh.vertices) for mesh, _ in geometry.parts]
    arrays += [np.asarray(p.vertices if p.vertices is not None else [*p.size, *p.pos]) for p in geometry.collision]
    return arrays


def _same(a: list[np.ndarray], b: list[np.ndarray]) -> bool:
    if len(a) != len(b):
        return False
    return all(x.shape == y.shape and np.allclose(x, y, rtol=0, atol=1e-9) for x, y in zip(a, b, strict=True))


def _changes_the_shape(build: Builder[Any], variants: list[Variant], name: str, hint: Any) -> bool:
    for variant in variants:
        params = build.parse(variant.options, variant.name)
        before = _signature(build.draw(variant, params))
        for value in _other_values(hint, getattr(params, name)):
            if not _same(before, _signature(build.draw(variant, replace(params, **{name: value})))):
                return True
    return False


@pytest.mark.long  # every builder of the catalogue, every parameter
@pytest.mark.parametrize("builder_name", sorted(_variants_by_builder()))
def test_every_parameter_changes_the_shape(builder_name: str) -> None:
    build, variants = _variants_by_builder()[builder_name]
    hints = get_type_hints(build.params)
    fields = dataclasses.fields(build.params)
    unread = [f.name for f in fields if not _changes_the_shape(build, variants, f.name, hints[f.name])]
    assert not unread, f"{builder_name}: parameters {unread} change nothing in any variant"
