"""The one writer of each data format: CSV (quoting as the csv module, atomic) and JSON (no NaN)."""

from __future__ import annotations

import csv
import io
import json
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from regimemap.io.csv import csv_line, csv_text, write_csv
from regimemap.io.json import json_text, write_json
from regimemap.records.numbers import rounded

cells = st.lists(st.text(alphabet=st.characters(codec="utf-8", exclude_categories=("Cs",))), min_size=1,
                 max_size=5)


@given(cells)
def test_a_csv_line_reads_back_as_its_cells(row: list[str]) -> None:
    line = csv_line(row)
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(row)
    assert line + "\n" == buf.getvalue()
    if row != [""] and not any("\r" in c for c in row):  # a blank line is skipped; csv leaves a CR bare
        assert next(csv.reader(io.StringIO(line + "\n", newline=""))) == row


def test_csv_text_and_file_are_the_same_bytes(tmp_path) -> None:
    rows = ["1,0.5", "2,0.25\n3,0.125"]  # a row, and several joined by a newline
    path = tmp_path / "t.csv"
    write_csv(path, ("n", "x"), iter(rows))
    assert path.read_bytes() == csv_text(("n", "x"), rows).encode() == b"n,x\n1,0.5\n2,0.25\n3,0.125\n"


def test_a_failed_csv_write_leaves_the_old_file(tmp_path) -> None:
    path = tmp_path / "t.csv"
    path.write_text("old")

    def rows():
        yield "1,2"
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_csv(path, ("a", "b"), rows())
    assert path.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["t.csv"]


def test_json_refuses_a_number_that_is_not_finite_and_writes_nothing(tmp_path) -> None:
    path = tmp_path / "r.json"
    with pytest.raises(ValueError):
        write_json(path, {"x": math.nan})
    assert not path.exists() and not list(tmp_path.iterdir())
    write_json(path, rounded({"x": math.nan, "y": [0.1 + 0.2, 3], "z": "é"}), indent=None, ascii_only=False)
    assert path.read_text(encoding="utf-8") == '{"x": null, "y": [0.3, 3], "z": "é"}\n'
    assert json.loads(json_text({"y": 1.5})) == {"y": 1.5}
