"""Diagnostics go through :mod:`logging` (``logging.getLogger("regimemap")`` and its children).

``regimemap -v`` shows the library's INFO records on standard error and
``-vv`` its DEBUG records too; without ``-v`` nothing but the command's own
output and notes; the library itself never prints.
"""

from __future__ import annotations

import ast
import logging
import re
from pathlib import Path

import pytest

from regimemap.caisson.file import example_design_text

from ..conftest import invoke_cli

SRC = Path(__file__).resolve().parents[2] / "src" / "regimemap"
#: A line of ``-v`` on standard error: ``regimemap: [  312 ms] INFO regimemap.io.atomic: wrote ...``.
RECORD = re.compile(r"^regimemap: \[ *\d+ ms\] (DEBUG|INFO|WARNING|ERROR) (regimemap(\.\w+)*): ")


def _records(stderr: str) -> list[tuple[str, str, str]]:
    out = []
    for line in stderr.splitlines():
        m = RECORD.match(line)
        if m:
            out.append((m.group(1), m.group(2), line[m.end():]))
    return out


def _lifetime_args(design: Path) -> list[str]:
    return ["lifetime", str(design), "--trials", "600", "--seed", "1", "--jobs", "1", "--quiet"]


# -- the command line ---------------------------------------------------------------------------------

def test_verbose_shows_the_main_steps(tmp_path):
    out = tmp_path / "map.npz"
    r = invoke_cli(["-v", "export", "--gamma", "3", "--kprime", "0.4", "-o", str(out)])
    assert r.code == 0, r.output
    recs = _records(r.stderr)
    assert {level for level, _, _ in recs} == {"INFO"}  # -v: no DEBUG
    assert any(name == "regimemap.maps.record_export" and "401 x 401 points" in msg for _, name, msg in recs), recs
    assert ("INFO", "regimemap.io.atomic", f"wrote {out} ({out.stat().st_size:,} bytes)") in recs
    assert r.stdout == f"{out}\n"  # standard output is the command's, with or without -v


def test_double_verbose_shows_the_details(goda):
    r = invoke_cli(["-vv", *_lifetime_args(goda)])
    assert r.code == 0, r.output
    recs = _records(r.stderr)
    names = {name for _, name, _ in recs}
    assert "regimemap.lifetime.parallel" in names
    chunks = [msg for level, name, msg in recs if level == "DEBUG" and msg.startswith("chunk ")]
    assert chunks and re.match(r"chunk 1/2: 500 lifetimes, \d+ sliding waves, \d+\.\d\d s$", chunks[0]), chunks
    assert any(level == "INFO" and msg.startswith("600 lifetimes of 50 years x 1 width in 2 chunks in this "
                                                   "process") for level, _, msg in recs), recs
    assert any(level == "INFO" and re.match(r"2 chunks done in \d+\.\d\d s", msg) for level, _, msg in recs)


@pytest.mark.parametrize("flag", ["--verbose", "-v"])
def test_verbose_is_an_option_of_the_group(flag, tmp_path):
    r = invoke_cli([flag, "classify", "--gamma", "3", "--kprime", "0.4", "--k", "0.5", "--mu", "0.8"])
    assert r.code == 0, r.output
    assert "-v, --verbose" in invoke_cli(["--help"]).stdout


def test_without_verbose_nothing_is_logged(tmp_path, goda):
    out = tmp_path / "map.npz"
    quiet = invoke_cli(["export", "--gamma", "3", "--kprime", "0.4", "-o", str(out)])
    loud = invoke_cli(["-v", "export", "--gamma", "3", "--kprime", "0.4", "-o", str(out)])
    assert quiet.code == loud.code == 0
    assert not _records(quiet.stderr) and "regimemap: [" not in quiet.stderr
    # the command's own notes stay as they are: -v only adds the records
    notes = [ln for ln in loud.stderr.splitlines() if not RECORD.match(ln)]
    assert notes == quiet.stderr.splitlines() and notes  # the "regimemap: npz, ... grid" note
    assert quiet.stdout == loud.stdout
    life = invoke_cli(_lifetime_args(goda))
    assert life.code == 0 and not _records(life.stderr), life.stderr


def test_each_run_removes_its_handler():
    """Commands run in one process (tests, notebooks) do not pile up handlers or keep the level."""
    logger = logging.getLogger("regimemap")
    before = (list(logger.handlers), logger.level)
    for args in (["-vv", "classify", "--gamma", "3", "--kprime", "0.4", "--k", "0.5", "--mu", "0.8"],
                 ["-v", "classify", "--gamma", "nope"]):
        invoke_cli(args)
        assert (list(logger.handlers), logger.level) == before


def test_a_failing_command_still_says_one_error_line(tmp_path):
    r = invoke_cli(["-vv", "export", "--gamma", "3", "--kprime", "0.4", "-o", str(tmp_path / "no" / "m.npz")])
    assert r.code == 2 and len(r.error_lines()) == 1, r.stderr


# -- the library ----------------------------------------------------------------------------------------

@pytest.mark.slow
def test_the_library_logs_its_main_steps(caplog, capsys, tmp_path):
    """Maps computed and their size, lifetime chunks and their timing, dynamics batches, files written:
    as records of ``regimemap.*`` loggers, and not one character printed."""
    from regimemap import Parameters
    from regimemap.dynamics import Block, outcome_map
    from regimemap.io.atomic import atomic_open
    from regimemap.lifetime import lifetime_sliding
    from regimemap.maps import compute_map

    caplog.set_level(logging.DEBUG, logger="regimemap")
    compute_map(Parameters(3.0, 0.4), samples=50)
    from regimemap.caisson.file import parse_design

    d = parse_design(example_design_text())
    lifetime_sliding(d.lifetime_caisson(), d.lifetime_model(), trials=300, seed=1, chunk=100)
    outcome_map(Block(B=1.0, gamma=0.5, mu=0.3), "rectangular", ("mu", [0.2, 0.6]), ("k_peak", [0.3, 0.5]),
                duration=0.3, refine=False)
    with atomic_open(tmp_path / "a.txt") as fh:
        fh.write("x")
    assert capsys.readouterr() == ("", "")
    got = [(r.name, r.levelname, r.getMessage()) for r in caplog.records]
    assert all(name.startswith("regimemap.") for name, _, _ in got)

    def has(name: str, level: str, pattern: str) -> bool:
        return any(n == name and lv == level and re.search(pattern, m) for n, lv, m in got)

    assert has("regimemap.maps.mapdata", "INFO", r"^map gamma=3, k'=0.4: view .* \d+ polygons \(\d+ vertices\)")
    assert has("regimemap.lifetime.parallel", "INFO", r"^300 lifetimes of 50 years x 1 width in 3 chunks")
    assert has("regimemap.lifetime.parallel", "DEBUG", r"^chunk 3/3: 100 lifetimes, \d+ sliding waves")
    assert has("regimemap.dynamics.outcome", "DEBUG", r"^batch of 4 runs \(rectangular pulses\)")
    assert has("regimemap.dynamics.outcome", "INFO", r"^outcome grid mu x k_peak: 2 x 2 = 4 runs")
    assert has("regimemap.io.atomic", "INFO", r"a\.txt \(1 bytes\)$")


def test_the_library_is_silent_by_default(capsys, caplog):
    """A NullHandler on ``regimemap``: no "No handlers could be found" and no lastResort output."""
    import regimemap  # noqa: F401

    logger = logging.getLogger("regimemap")
    assert any(isinstance(h, logging.NullHandler) for h in logger.handlers)
    assert logger.level == logging.NOTSET  # the application chooses the level


def _prints(path: Path) -> list[str]:
    """Calls of ``print``, ``click.echo`` and uses of ``sys.stdout``/``sys.stderr`` in a module."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "print":
            found.append(f"{path.name}:{node.lineno} print()")
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.value.id == "sys" and node.attr in ("stdout", "stderr", "__stdout__", "__stderr__"):
                found.append(f"{path.name}:{node.lineno} sys.{node.attr}")
            if node.value.id == "click" and node.attr in ("echo", "secho"):
                found.append(f"{path.name}:{node.lineno} click.{node.attr}")
    return found


LIBRARY = sorted(p for p in SRC.rglob("*.py") if "cli" not in p.relative_to(SRC).parts
                 and p.name != "__main__.py")


@pytest.mark.parametrize("path", LIBRARY, ids=lambda p: str(p.relative_to(SRC)))
@pytest.mark.slow
def test_library_code_never_prints(path):
    """Outside ``cli/`` diagnostics are log records: no print, no sys.stdout/stderr, no click.echo
    (the ``>>> print(...)`` of a docstring example is text, not code)."""
    assert _prints(path) == []
