"""cli/_writing.py: the -o files distinct, each written once, the figure drawn once."""

from __future__ import annotations

from pathlib import Path

import click
import pytest

from regimemap.cli._main import RunError
from regimemap.cli._writing import distinct_files, file_suffix, write_files


def test_the_same_file_twice_however_spelt(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(click.BadParameter, match="the same file is given twice"):
        distinct_files(["a.svg", "./a.svg"], "'-o'")
    distinct_files(["a.svg", "a.png"], "'-o'")


def test_data_written_by_its_writer_and_the_figure_drawn_once(tmp_path: Path) -> None:
    from matplotlib.figure import Figure

    drawn: list[Figure] = []

    def draw() -> Figure:
        drawn.append(Figure(figsize=(1, 1)))
        return drawn[-1]

    paths = [str(tmp_path / n) for n in ("a.svg", "t.csv", "b.png")]
    got = write_files(paths, draw, data_formats=("csv",), write_data=lambda p: Path(p).write_text("x\n"))
    assert got == paths and len(drawn) == 1
    assert (tmp_path / "t.csv").read_text() == "x\n"
    assert (tmp_path / "a.svg").read_bytes().startswith(b"<?xml")
    assert (tmp_path / "b.png").read_bytes()[:4] == b"\x89PNG"
    assert file_suffix("X.SVG") == "svg" and file_suffix("noext") == ""


def test_no_figure_file_draws_nothing(tmp_path: Path) -> None:
    def draw() -> None:
        raise AssertionError("drawn")

    assert write_files([], draw) == []  # type: ignore[arg-type]


def test_a_file_that_cannot_be_written_is_one_line(tmp_path: Path) -> None:
    bad = str(tmp_path / "no" / "t.csv")

    def write(path: str) -> None:
        open(path, "w")

    with pytest.raises(RunError, match=f"cannot write {bad}: No such file"):
        write_files([bad], lambda: None, data_formats=("csv",), write_data=write)  # type: ignore[arg-type,return-value]
