"""The one registry of file formats (:mod:`regimemap.io.formats`): every suffix it declares
resolves, an unknown one is the one error wherever it is met, and the figure suffixes the
commands' help lists are the registry's tuple."""

from __future__ import annotations

import re

import click
import pytest

from regimemap.cli import cli
from regimemap.io.formats import (
    FIGURE_FORMATS,
    FORMATS,
    RECORDS,
    SuffixError,
    format_for,
    kind_of,
    record_formats,
    suffix_error,
    suffix_of,
)


def test_every_declared_suffix_resolves():
    assert len({f.suffix for f in FORMATS}) == len(FORMATS)  # each format declared once
    for f in FORMATS:
        assert kind_of(f.suffix) == kind_of("." + f.suffix.upper()) == f.kind
    assert FIGURE_FORMATS == ("png", "svg", "pdf")
    for record in RECORDS:
        for suffix in record_formats(record):
            assert kind_of(suffix) is not None, f"{record}: .{suffix} is not a declared format"
            assert format_for(f"out/x.{suffix.upper()}", record) == suffix


@pytest.mark.parametrize("path,message", [
    ("run.txt", "unknown file suffix .txt in 'run.txt'; use .npz or .csv for the time history"),
    ("run", "no file suffix in 'run'; use .npz or .csv for the time history"),
    ("a.b/run.svg", "unknown file suffix .svg in 'a.b/run.svg'; use .npz or .csv for the time history"),
])
def test_an_unknown_suffix_is_the_one_error(path, message):
    with pytest.raises(SuffixError) as got:
        format_for(path, "time history")
    assert str(got.value) == message == str(suffix_error(path, "time history"))
    assert isinstance(got.value, ValueError) and kind_of(suffix_of(path)) != "data"


def test_a_record_of_two_parts_lists_both():
    with pytest.raises(SuffixError, match=r"^unknown file suffix \.json in 'l\.json'; use \.png, \.svg or "
                                          r"\.pdf for the figure, \.csv or \.npz for the lifetimes$"):
        format_for("l.json", "lifetime")


#: One file of a bad suffix for each command that writes files, and the option it is given to.
BAD_OUTPUTS = [
    (["plot", "--gamma", "3", "--kprime", "0.4", "-o", "{d}/x.txt"], "'-o' / '--output'"),
    (["atlas", "--gamma", "1", "--kprime", "0", "-o", "{d}/x.txt"], "'-o' / '--output'"),
    (["animate", "--gamma", "1", "--kprime", "0:0.5:2", "-o", "{d}/x.txt"], "'-o' / '--output'"),
    (["export", "--gamma", "3", "--kprime", "0.4", "-o", "{d}/x.txt"], "'-o' / '--output'"),
    (["simulate", "--gamma", "3", "--half-width", "0.2", "--mu", "5", "--pulse", "half-sine",
      "--k-peak", "0.5", "--duration", "0.5", "-o", "{d}/x.txt"], "'--output'"),
    (["outcome", "--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--mu", "5", "--pulse", "half-sine",
      "--k-peak", "0.3:1:2", "--duration", "0.2,0.5", "-o", "{d}/x.txt"], "'--output'"),
    (["lifetime", "DESIGN", "-o", "{d}/x.txt"], "'--output'"),
    (["caisson", "DESIGN", "-o", "{d}/x.txt"], "'--output'"),
]


@pytest.mark.parametrize("args,hint", BAD_OUTPUTS, ids=[a[0] for a, _ in BAD_OUTPUTS])
def test_every_command_words_an_unknown_suffix_once(run_cli, tmp_path, args, hint):
    design = tmp_path / "goda.toml"
    from regimemap.caisson.file_example import example_design_text

    design.write_text(example_design_text(), encoding="utf-8")
    argv = [str(design) if a == "DESIGN" else a.format(d=tmp_path) for a in args]
    run = run_cli(argv)
    assert run.code == 2 and run.stdout == ""
    [line] = run.stderr.splitlines()
    assert re.fullmatch(rf"regimemap {args[0]}: error: Invalid value for {re.escape(hint)}: unknown file "
                        rf"suffix \.txt in '{re.escape(str(tmp_path))}/x\.txt'; use \.[a-z].* for [a-z].*"
                        rf" \(see 'regimemap {args[0]} --help'\)", line), line
    assert not (tmp_path / "x.txt").exists()


def _output_helps() -> dict[str, str]:
    """The help of each option that names a file to draw in, by ``command option``."""
    found = {}
    for name, command in cli.commands.items():  # type: ignore[attr-defined]
        for param in command.params:
            if isinstance(param, click.Option) and param.help and ".svg" in param.help:
                found[f"{name} {param.opts[-1]}"] = param.help
    return found


def test_the_help_lists_the_registry_figure_suffixes():
    helps = _output_helps()
    assert {"plot --output", "figure --output", "atlas --output", "simulate --plot", "outcome --output",
            "lifetime --output", "caisson --output", "climate --output", "study --output"} <= set(helps)
    for where, text in helps.items():
        named = set(re.findall(r"(?<![\w/<])\.([a-z][a-z0-9]*)\b", text))
        assert all(kind_of(s) is not None for s in named), (where, named)
        assert {s for s in named if kind_of(s) == "figure"} == set(FIGURE_FORMATS), where
