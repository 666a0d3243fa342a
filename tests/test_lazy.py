"""The lazy loader of every package's ``__init__`` (:func:`regimemap._lazy.attach`), on a package of its own."""

from __future__ import annotations

import sys

import pytest

from regimemap._lazy import attach, typed_imports


@pytest.fixture
def package(tmp_path, monkeypatch):
    """A package ``lazypkg`` with two submodules (one of them a subpackage's) and a lazy ``__init__``."""
    root = tmp_path / "lazypkg"
    (root / "inner").mkdir(parents=True)
    (root / "alpha.py").write_text("VALUE = object()\ndef f():\n    return 1\n")
    (root / "inner" / "__init__.py").write_text("")
    (root / "inner" / "beta.py").write_text("B = 2\n")
    (root / "__init__.py").write_text(
        "from typing import TYPE_CHECKING\n"
        "from regimemap._lazy import attach\n"
        "if TYPE_CHECKING:\n"
        "    from .alpha import VALUE, f\n"
        "    from .inner.beta import B\n"
        "EAGER = 0\n"
        "__getattr__, __dir__ = attach(__name__, __file__)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import lazypkg

    yield lazypkg
    for name in [m for m in sys.modules if m == "lazypkg" or m.startswith("lazypkg.")]:
        del sys.modules[name]


def test_names_import_their_submodule_on_first_use(package):
    assert "lazypkg.alpha" not in sys.modules and "lazypkg.inner.beta" not in sys.modules
    assert package.f() == 1 and "lazypkg.alpha" in sys.modules
    assert "lazypkg.inner.beta" not in sys.modules  # only the submodule of the name read
    assert package.B == 2 and package.B is sys.modules["lazypkg.inner.beta"].B


def test_resolved_names_are_kept_in_the_package(package):
    value = package.VALUE
    assert vars(package)["VALUE"] is value is sys.modules["lazypkg.alpha"].VALUE


def test_dir_lists_every_name_before_any_is_imported(package):
    assert {"VALUE", "f", "B", "EAGER"} <= set(dir(package))
    assert dir(package) == sorted(dir(package))
    assert "lazypkg.alpha" not in sys.modules


def test_unknown_names_raise_attribute_error_naming_the_package(package):
    with pytest.raises(AttributeError, match="module 'lazypkg' has no attribute 'nope'"):
        package.nope  # noqa: B018
    assert not hasattr(package, "also_nope")


def _init(tmp_path, typed: str) -> str:
    path = tmp_path / "__init__.py"
    path.write_text(f"if TYPE_CHECKING:\n{typed}", encoding="utf-8")
    return str(path)


def test_the_names_are_the_typed_imports_by_submodule(tmp_path):
    path = _init(tmp_path, "    from .a import x, y\n    from ..sibling.b import z\n    pass\n    from .a import w\n")
    assert typed_imports(path) == {"a": ["x", "y", "w"], ".sibling.b": ["z"]}


def test_a_name_under_two_submodules_is_refused(tmp_path):
    with pytest.raises(ValueError, match="'x' listed under 'a' and 'b'"):
        attach("somepkg", _init(tmp_path, "    from .a import x\n    from .b import x\n"))


@pytest.mark.parametrize("typed", ["    from a import x\n", "    from .a import x as y\n", "    import os\n"])
def test_an_import_the_package_could_not_give_by_its_name_is_refused(tmp_path, typed):
    with pytest.raises(ValueError, match="__init__.py:2: a lazy name is a relative 'from .module import name'"):
        typed_imports(_init(tmp_path, typed))
