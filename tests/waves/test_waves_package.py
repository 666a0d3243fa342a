"""Package hygiene: numpy-only library code, no imports from the rest of regimemap."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import numpy as np

import regimemap.waves
from regimemap.waves import goda_pressures

SRC = Path(regimemap.waves.__file__).resolve().parent
FILES = sorted(SRC.glob("*.py")) + [SRC.parent / "caisson" / "file.py"]
ALLOWED = {"numpy", "regimemap", "tomllib", "tomli"} | set(sys.stdlib_module_names)


def imported_modules(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module)
    return names


def test_library_code_imports_numpy_and_stdlib_only() -> None:
    for path in FILES:
        for name in imported_modules(path):
            assert name.split(".")[0] in ALLOWED, f"{path.name} imports {name}"
            if name.startswith("regimemap"):
                # the design file also builds the lifetime model of its [lifetime] table
                allowed = ("regimemap.waves", "regimemap.lifetime") if path.parent.name == "caisson" else (
                    "regimemap.waves",)
                assert name.startswith(allowed), f"{path.name} imports {name}"


def test_every_public_name_has_a_docstring() -> None:
    for name in regimemap.waves.__all__:
        obj = getattr(regimemap.waves, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name


def test_rotation_broadcasts_like_the_other_arguments() -> None:
    pr = goda_pressures(Hmax=8.0, period=11.4, depth=10.1, hb=10.4, armour_depth=5.6, base_depth=7.1,
                        crest=3.4, angle_deg=20.0, rotation_deg=np.array([0.0, 5.0, 15.0, 20.0]))
    np.testing.assert_array_equal(pr.beta, [20.0, 15.0, 5.0, 0.0])
    assert pr.p1.shape == (4,)
