"""The one declaration of an input file's keys and its reader (``regimemap.io.toml_keys``)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import pytest

from regimemap.io.toml_errors import DesignFileError
from regimemap.io.toml_keys import KINDS, Key, KeyReader, default_of, example_table, key, keys_of, load_toml


@dataclass(frozen=True)
class _Table:
    depth: float = key("a depth > 0 in metres", lambda x: x > 0.0, why=lambda x: f"{x:g} m is no depth",
                       example="depth = 1.0   # m")
    count: int = key("a whole number >= 1", lambda x: x >= 1, kind="int", default=1)
    name: str = key('"a" or "b"', lambda x: x in ("a", "b"), kind="text", default="a",
                    example='# name = "b"')
    flag: bool = key("true or false", kind="bool", default=False)
    values: tuple[float, ...] | None = key("a list of numbers > 0", lambda x: x > 0.0, kind="numbers",
                                           default=None)
    pair: tuple[float, float] | None = key("[ratio, cov]", kind="pair", default=None)
    limits: dict[float, float] = key("{sliding = p}", kind="limits", factory=dict)


TEXT = """[t]
depth = -2.0
count = 0
name = "c"
flag = 1
values = [1.0, -1.0]
pair = [0.0, 0.1]
"""


def _reader() -> KeyReader:
    return KeyReader("x.toml", TEXT, {"t": keys_of(_Table)})


def test_the_fields_are_the_keys_in_order_with_their_defaults_and_example():
    keys = keys_of(_Table)
    assert list(keys) == ["depth", "count", "name", "flag", "values", "pair", "limits"]
    assert all(isinstance(k, Key) and k.kind in KINDS for k in keys.values())
    assert keys["depth"].required and not keys["count"].required and not keys["limits"].required
    assert default_of(_Table, "count") == 1 and default_of(_Table, "limits") == {}
    assert example_table("t", _Table) == '[t]\ndepth = 1.0   # m\n# name = "b"\n'
    assert keys["count"].reason(0) == "out of range" and keys["depth"].reason(-2.0) == "-2 m is no depth"


@pytest.mark.parametrize(("name", "value", "message"), [
    ("depth", -2.0, "x.toml, line 2: [t] depth = -2.0: -2 m is no depth; accepted: a depth > 0 in metres"),
    ("depth", "1", "x.toml, line 2: [t] depth = -2.0: expected a number, found a string; accepted: "),
    ("count", 0, "x.toml, line 3: [t] count = 0: out of range; accepted: a whole number >= 1"),
    ("count", 1.0, "[t] count = 0: expected a whole number, found a float"),
    ("name", "c", 'x.toml, line 4: [t] name = "c": not one of the accepted values; accepted: "a" or "b"'),
    ("flag", 1, "x.toml, line 5: [t] flag = 1: expected true or false, found an integer"),
    ("values", [1.0, -1.0], "[t] values = [1.0, -1.0]: -1.0 in the list is out of range"),
    # the value as the file writes it (here the file's line, not the value handed in)
    ("values", [1.0, "x"], "[t] values = [1.0, -1.0]: expected numbers, found 'x' in the list is a string"),
    ("pair", [0.0, 0.1], "x.toml, line 7: [t] pair = [0.0, 0.1]: the ratio 0.0 is not > 0"),
    ("limits", {"0": {"1": 2.0}}, "the probability 2.0 of 0.1 m is not in [0, 1]"),
])
def test_a_value_is_read_as_its_kind_and_refused_with_its_line_and_words(name: str, value: Any, message: str):
    with pytest.raises(DesignFileError) as info:
        _reader().value("t", {name: value}, name)
    assert message in str(info.value)


def test_a_table_is_its_dataclass_and_its_names_are_checked():
    r = _reader()
    assert r.table("t", {"depth": 2}, _Table) == _Table(depth=2.0)
    assert r.value("t", {"limits": {"0": {"1": 0.2}}}, "limits") == {0.1: 0.2}
    with pytest.raises(DesignFileError, match=r"^x\.toml, line 1: \[t\] depth is missing; accepted: a depth"):
        r.table("t", {}, _Table)
    with pytest.raises(DesignFileError, match=r"unknown key \[t\] dept \(did you mean 'depth'\?\); accepted keys"):
        r.check_keys("t", {"dept": 1.0})


def test_a_toml_syntax_error_gives_its_line_and_column():
    def error(msg: str, line: int | None, column: int | None) -> ValueError:
        return ValueError(f"{line}:{column}: {msg}")

    assert load_toml("a = 1\n", error) == {"a": 1}
    with pytest.raises(ValueError, match=r"^2:\d+: "):
        load_toml("a = 1\nb = = 2\n", error)
