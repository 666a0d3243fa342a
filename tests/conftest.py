"""Shared test settings: hypothesis profiles, a headless matplotlib, and the fixtures of every folder.

The tests mirror the folders: a product's (``tests/<product>/``: maps, caisson, motion, lifetime,
climate, study, with the tests of its commands) and a shared package's (``tests/<package>/``:
mechanics, waves, dynamics, io, drawing, cli); the tests of the whole package stay at the top (the layers, the public API,
the lazy loader, the README, the packaging, the notebook reprs), with the helpers shared across
folders (``_sweep.py``, ``_writers.py``).

Hypothesis profiles (choose with ``HYPOTHESIS_PROFILE=name`` in the
environment, or ``pytest --hypothesis-profile=name``):

``quick`` (the default)
    few examples, derandomized (the same examples every run), no deadline:
    the whole suite stays fast and never flakes.
``ci``
    more examples, still derandomized; for the continuous-integration job.
``thorough``
    many random examples, for a long local run when changing the engine
    (``--hypothesis-seed=N`` makes it repeatable, on every xdist worker alike).

``quick`` and ``ci`` keep no example database either, so ``pytest -n auto``
runs exactly the examples a serial run does.  The tiers (``render``,
``subprocess``, ``slow``: ``make test-fast`` leaves them out) are listed in
pyproject.toml; ``preset_maps`` (below) shares the report's computed maps.
"""

from __future__ import annotations

import os
from typing import Any

import matplotlib

matplotlib.use("Agg")  # before anything imports pyplot; no window ever opens

try:
    from hypothesis import HealthCheck, settings
except ImportError:  # pragma: no cover - hypothesis is a test dependency
    settings = None  # type: ignore[assignment]
else:
    _common = dict(deadline=None, suppress_health_check=[HealthCheck.too_slow],
                   print_blob=True)
    # derandomize and no example database: every pytest-xdist worker, and every run, tries the
    # same examples (a saved failing example would be replayed by one worker only)
    settings.register_profile("quick", max_examples=25, derandomize=True, database=None, **_common)
    settings.register_profile("ci", max_examples=150, derandomize=True, database=None, **_common)
    settings.register_profile("thorough", max_examples=2000, **_common)
    settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "quick"))


# -- running the command line in-process ---------------------------------------------------------------

import dataclasses  # noqa: E402
from pathlib import Path  # noqa: E402

import pytest  # noqa: E402


@dataclasses.dataclass
class CliRun:
    """What a user sees from one run of ``regimemap``: exit code, stdout, stderr."""

    code: int
    stdout: str
    stderr: str

    @property
    def output(self) -> str:
        return self.stdout + self.stderr

    def error_lines(self) -> list[str]:
        return [ln for ln in self.stderr.splitlines() if "error:" in ln or "interrupted" in ln]


def invoke_cli(args: list[str], env: dict[str, str | None] | None = None) -> CliRun:
    """Run ``regimemap ARGS`` as :func:`regimemap.cli.main` does (through ``run_main``).

    Exceptions are *not* caught here: one escaping ``run_main`` is a bug the
    test must see.
    """
    from click.testing import CliRunner

    from regimemap.cli import cli
    from regimemap.cli._main import run_main

    runner = CliRunner()
    full_env = {"REGIMEMAP_DEBUG": None, "COLUMNS": "100"}
    full_env.update(env or {})
    with runner.isolation(env=full_env) as streams:
        code = run_main(cli, list(args))
        out, err = streams[0], streams[1]
        import sys

        sys.stdout.flush()
        sys.stderr.flush()
        stdout = out.getvalue().decode("utf-8", "replace")
        stderr = err.getvalue().decode("utf-8", "replace")
    return CliRun(code, stdout, stderr)


@pytest.fixture(scope="session")
def run_cli():
    """A function ``run_cli(args) -> CliRun`` (session-scoped, so hypothesis tests may use it)."""
    return invoke_cli


# -- the design files ----------------------------------------------------------------------------------

@pytest.fixture
def goda(tmp_path: Path) -> Path:
    """Goda's caisson: the example design file (``regimemap caisson --example``) as ``tmp_path/goda.toml``.

    A test that needs the design as data rather than as a file defines a fixture of another name.
    """
    from regimemap.caisson.file import example_design_text

    path = tmp_path / "goda.toml"
    path.write_text(example_design_text(), encoding="utf-8")
    return path


#: A year of a buoy's sea states (NDBC 44007, 1996): the record of :func:`band_design`.
BUOY_RECORD = Path(__file__).resolve().parent / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"


def band_design(d: Path, replicates: int = 400) -> Path:
    """The example design with the buoy's record for its climate: ``d/site.toml``, its ``[lifetime]``
    climate keys replaced by ``climate_replicates`` and a ``[lifetime.record]`` of ``d/buoy.txt.gz``
    (:data:`BUOY_RECORD`, copied), so that a run draws its band of replicate climates."""
    import shutil

    from regimemap.caisson.file import example_design_text

    shutil.copy(BUOY_RECORD, d / "buoy.txt.gz")
    text = example_design_text()
    i, j = text.index("[lifetime]"), text.index("[lifetime.errors]")
    climate = ("H0_10", "H0_50", "annual_maxima", "distribution", "shape", "storms_per_year")
    kept = [ln for ln in text[i:j].splitlines() if ln.split("=")[0].strip() not in climate]
    life = ("\n".join(kept) + f"\nclimate_replicates = {replicates}\n\n[lifetime.record]\npath = \"buoy.txt.gz\"\n"
            "threshold = \"98%\"\n\n")
    f = d / "site.toml"
    f.write_text(text[:i] + life + text[j:], encoding="utf-8")
    return f


# -- the report's figures, computed once ----------------------------------------------------------------

class _PresetMaps(dict):
    """``preset_maps[fid]``: the :class:`~regimemap.maps.MapData` of the report's figure ``fid``
    (its preset's block, view, modes and raw flag), computed on first use and kept for the session."""

    def __missing__(self, fid: str):
        from regimemap.maps.figures.presets import get_preset
        from regimemap.maps.mapdata import compute_map

        pr = get_preset(fid)
        data = compute_map(pr.params, k_max=pr.k_max, mu_max=pr.mu_max, modes=pr.modes, raw=pr.raw)
        self[pr.id] = data
        return data


@pytest.fixture(scope="session")
def preset_maps() -> _PresetMaps:
    """The computed maps of the report's figures, shared by every test of a session (of an xdist
    worker): ``preset_maps["3.9a"]``.  Read-only: a test that changes one must copy it."""
    return _PresetMaps()


def draw_sheet(report: Any, *, required: tuple[float, float] = (1.2, 1.2), lifetime: Any = None,
               checks: Any = None, **kw: Any) -> Any:
    """The design sheet as ``regimemap caisson -o`` draws it: the view, map and checks computed first.

    The checks default to the caisson's (:func:`regimemap.caisson.report.caisson_checks` of
    ``required``) and those of ``lifetime``.
    """
    from regimemap.caisson.figures.page import sheet_figure
    from regimemap.caisson.report import caisson_checks, sheet_map

    view, data = sheet_map(report)
    if checks is None:
        checks = [*caisson_checks(report, required), *(() if lifetime is None else lifetime.checks)]
    return sheet_figure(report, view=view, data=data, checks=checks, required=required,
                        lifetime=lifetime, **kw)
