"""Quantities at the input boundary: conversion to SI and errors."""

from __future__ import annotations

import math

import pytest

from kegel import KegelInputError, parse_quantity


@pytest.mark.parametrize(
    "text, kind, si",
    [
        ("6 kN", "force", 6000.0),
        ("1349 lbf", "force", 1349 * 4.4482216152605),
        ("2000 rpm", "speed", 2000 * 2 * math.pi / 60),
        # frequencies count revolutions (issue 21: "33.3333 Hz" ran at 318 rpm, 2 pi too slow)
        ("33.3333 Hz", "speed", 33.3333 * 2 * math.pi),
        ("2000 1/min", "speed", 2000 * 2 * math.pi / 60),
        ("10 1/s", "speed", 10 * 2 * math.pi),
        ("10 rad/s", "speed", 10.0),
        ("360 deg/s", "speed", 2 * math.pi),
        ("1 revolution/s", "speed", 2 * math.pi),
        ("50 degC", "temperature", 323.15),
        ("122 degF", "temperature", 323.15),
        ("20 um", "length", 20e-6),
        ("2 mrad", "angle", 2e-3),
        ("50 N m", "moment", 50.0),
        ("0.1 s", "time", 0.1),
    ],
)
def test_conversion_to_si(text, kind, si):
    assert parse_quantity(text, kind, source="f.toml", key="k") == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize(
    "value, kind, fragment",
    [
        ("6 kg", "force", "[mass]"),
        ("6", "force", "no unit"),
        (6, "force", "quoted string"),
        ("six kN", "force", "a force"),
        ("inf kN", "force", "finite"),
        ("0.002", "angle", "no unit"),
    ],
)
def test_errors_name_source_key_value(value, kind, fragment):
    with pytest.raises(KegelInputError) as info:
        parse_quantity(value, kind, source="scene.toml", key="operating.x")
    msg = str(info.value)
    assert msg.startswith("scene.toml: key 'operating.x' = ") and repr(value) in msg and fragment in msg
