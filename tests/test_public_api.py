"""The public API, pinned (after pyhf's ``test_public_api.py``).

Each package's ``__all__`` is its public API.  Changing it on purpose means
changing the list here in the same commit; changing it by accident fails.
"""

from __future__ import annotations

import importlib

import pytest

PUBLIC_API = {
    "regimemap": [
        "Case", "Hypothesis", "LOADED_MAP_MODES", "MAP_MODES", "Mode", "PRIORITY", "Parameters",
        "PointResult", "SELECTION_ORDER", "__version__", "admissible", "classify", "label_grid", "margin", "query_point",
        "query_points",
    ],
    "regimemap.mechanics": [
        "Case", "Curve", "Hypothesis", "LOADED_MAP_MODES", "MAP_MODES", "Mode", "NamedPoint",
        "PRIORITY", "Parameters", "RAW_REGIONS", "Response", "SELECTION_ORDER", "TOLERANCE",
        "admissible", "admissible_hypotheses", "case_of", "choose", "least_constraint", "map_curves",
        "named_points", "raw_region", "solve",
    ],
    "regimemap.maps": [
        "AmbiguousRegion", "Crossing", "CurveData", "DEFAULT_SAMPLES", "DesignPoint", "MapData",
        "Margin", "PointResult", "ambiguous_regions", "auto_extent", "classify", "column_segments",
        "compute_map", "label_grid", "margin", "query_point", "query_points", "region_polygons",
    ],
    "regimemap.drawing": [
        "FIGSIZE", "MODE_STYLE", "MapArtists", "MapStyle", "atlas_figure", "default_title", "draw_ambiguity",
        "draw_design_points", "draw_map", "fit_figure", "load_matplotlib", "map_figure", "new_figure", "render_map",
        "render_preset", "style_context",
        # figures to files, atomically (through regimemap.io.atomic, the layer below)
        "save_figure", "write_animation", "write_atlas",
        # outcome maps and motions after initiation (regimemap.dynamics)
        "OUTCOME_STYLE", "draw_outcome_map", "motion_figure", "outcome_figure",
        "OutcomeStyle",
        # a caisson's sliding over its design life (regimemap.lifetime)
        "chart_figure", "lifetime_figure",
        # a wave record's extremes (regimemap.climate)
        "climate_figure", "diagnostics_figure",
        # a whole breakwater (regimemap study)
        "study_figure",
    ],
    "regimemap.io": [
        "atomic_open", "atomic_path", "export_map", "format_result", "parse_point_spec",
        "read_points_csv", "result_row",
        # simulations after initiation: pulse files, time histories, outcome maps
        "read_pulse_csv", "write_history", "write_outcome",
        # wave records (regimemap climate)
        "read_record",
    ],
    "regimemap.study": [
        "Study", "StudyCheck", "StudyFileError", "StudyRecord", "StudyRow", "example_study_text",
        "read_study", "run_study", "study_figure",
    ],
    "regimemap.caisson": [
        "CaissonError", "CaissonNumbers", "CaissonRecord", "Design", "DesignFileError",
        "ImplausibleDesignError", "caisson_sheet", "example_design_text", "parse_design", "read_design",
        "run_caisson",
    ],
    "regimemap.motion": [
        "DynamicsFigureRecord", "OutcomeRecord", "SimulationRecord", "motion_figure", "outcome_figure",
        "run_dynamics_figure", "run_outcome", "run_simulation",
    ],
    "regimemap.lifetime": [
        "ADDED_MASS_COEFFICIENT", "Caisson", "Climate", "ClusterUnavailable", "DEFAULT_ERRORS",
        "DEFAULT_THRESHOLDS", "DISTRIBUTIONS", "DesignChart", "ErrorFactor", "Errors", "Failure",
        "LifetimeModel", "LifetimeResult", "Requirements", "added_mass", "available_cores", "design_chart",
        "half_sine_slide", "judge_chart", "judge_lifetime", "lifetime_sliding", "sf_width", "wave_duration",
        "YearTrend",
    ],
    "regimemap.climate": [
        "AM_DISTRIBUTIONS", "METHODS", "POT_DISTRIBUTIONS", "AnnualMaxima", "Band", "ClimateOptions",
        "ClimateResult", "Fit", "Quality", "Record", "Storms", "analyse", "annual_maxima", "bootstrap", "fit",
        "make_record", "parse_threshold", "storms",
    ],
    "regimemap.dynamics": [
        "Block", "CATEGORY_LABELS", "DESIGN_INPUTS", "DESIGN_UNITS", "FREE_STEP", "G", "History",
        "NO_ADDED_MASS", "OVERTURN", "OutcomeMap", "PROFILE", "PULSE_STEPS", "Phase", "Pulse", "REST", "ROCK",
        "SHAPES", "SLIDE", "SLIDE_ROCK", "STILL_MOVING", "SWEEPABLE", "Simulation", "default_steps",
        "design_wave_inputs", "design_wave_numbers", "design_wave_run",
        "frequency_parameter", "from_dimensionless", "outcome_map", "simulate", "size_R", "slenderness",
        "to_dimensionless",
    ],
    "regimemap.waves": [
        "CaissonAnalysis", "CaissonLoads", "CaissonSection", "Densities", "DesignHeights", "EquivalentBlock",
        "GODA_ROTATION_DEG", "GodaPressures", "HMAX_FACTOR", "RestCheck", "Stability", "analyse_caisson",
        "breaker_height", "caisson_loads", "deep_water_wavelength", "design_heights", "effective_angle",
        "equivalent_block", "given_heights", "goda_pressures", "heel_pressure", "impulsive_coefficient",
        "linear_shoaling_coefficient", "section_from_densities", "section_from_weight", "shoaling_coefficient",
        "stability", "static_rest_check", "wave_duration", "wavelength", "wavenumber",
    ],
    "regimemap.workflows": [
        "Field", "Notice", "Record",
        "AnimationRecord", "AtlasRecord", "MapRecord", "QueryRecord", "points_of_map", "run_animation",
        "run_atlas", "run_map", "run_query",
        "CaissonError", "CaissonNumbers", "CaissonRecord", "ImplausibleDesignError", "run_caisson",
        "DynamicsFigureRecord", "OutcomeRecord", "SimulationRecord", "run_dynamics_figure", "run_outcome",
        "run_simulation",
        "ChartRecord", "ClimateRecord", "LifetimeDesign", "LifetimeRecord", "read_lifetime_design",
        "run_chart", "run_climate", "run_lifetime",
        "StudyRecord", "StudyRow", "run_study",
    ],
    "regimemap.cli": ["cli", "console_main", "main"],
}


@pytest.mark.parametrize("package", sorted(PUBLIC_API))
def test_public_api_is_pinned(package):
    mod = importlib.import_module(package)
    assert sorted(mod.__all__) == sorted(PUBLIC_API[package])


@pytest.mark.parametrize("package", sorted(PUBLIC_API))
def test_every_public_name_resolves(package):
    mod = importlib.import_module(package)
    for name in mod.__all__:
        assert getattr(mod, name) is not None, f"{package}.{name}"


@pytest.mark.subprocess
@pytest.mark.parametrize("package", ["regimemap.drawing", "regimemap.io", "regimemap.lifetime"])
def test_lazy_packages_list_their_names_in_dir(package):
    """``dir()`` of a lazy package shows its public names before any of them is imported."""
    import subprocess
    import sys

    code = (f"import {package} as m, sys\n"
            "assert set(m.__all__) <= set(dir(m)), sorted(set(m.__all__) - set(dir(m)))\n"
            "print('matplotlib' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"  # listing the names imports none of them


@pytest.mark.subprocess
def test_reading_a_record_does_not_import_scipy():
    """The readers and the record's quality control need numpy only: a record refused at the
    command line is refused before scipy's second of imports."""
    import subprocess
    import sys

    code = "import regimemap.climate.file, regimemap.climate.wave_record, sys\nprint('scipy' in sys.modules)\n"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


@pytest.mark.subprocess
def test_a_lifetime_without_a_record_does_not_import_scipy_stats(tmp_path):
    """Goda's climate and the lifetime engine need scipy.special only: scipy.stats and
    scipy.optimize (over a second of imports) wait for a fit to data."""
    import subprocess
    import sys

    design = tmp_path / "goda.toml"
    subprocess.run([sys.executable, "-m", "regimemap", "caisson", "--example"], check=True,
                   stdout=design.open("w"))
    code = ("import atexit, sys\n"
            "atexit.register(lambda: print(sorted(m for m in ('scipy.stats', 'scipy.optimize')\n"
            "                                     if m in sys.modules), file=sys.stderr))\n"
            "from regimemap.cli import console_main\n"
            f"sys.argv = ['regimemap', 'lifetime', {str(design)!r}, '--trials', '20', '--jobs', '1']\n"
            "console_main()\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stderr.strip().splitlines()[-1] == "[]", out.stderr


@pytest.mark.parametrize("package", sorted(PUBLIC_API))
def test_dir_lists_every_public_name(package):
    """``dir(package)`` (what IDEs and tab completion show) lists the whole ``__all__``, lazy names too."""
    mod = importlib.import_module(package)
    missing = set(mod.__all__) - set(dir(mod))
    assert not missing, f"{package}: not in dir(): {sorted(missing)}"


def _lazy_view(package: str) -> tuple[set[str], dict[str, set[str]], dict[str, set[str]], bool]:
    """What a package's ``__init__`` says, read from its source: (names bound when the module runs,
    names imported under ``if TYPE_CHECKING:`` by submodule, the names :func:`regimemap._lazy.attach`
    imports on first use by submodule -- read from those imports, when it is given the package's
    ``__name__`` and ``__file__`` --, ``attach`` called under ``if not TYPE_CHECKING:``)."""
    import ast
    from pathlib import Path

    from regimemap._lazy import typed_imports

    path = Path(importlib.import_module(package).__file__)
    tree = ast.parse(path.read_text(encoding="utf-8"))
    bound: set[str] = set()
    typed: dict[str, set[str]] = {}
    lazy: dict[str, set[str]] = {}
    hidden = False
    for node in tree.body:
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
            for n in ast.walk(node):
                if isinstance(n, ast.ImportFrom):
                    typed.setdefault("." * (n.level - 1) + (n.module or ""), set()).update(a.asname or a.name for a in n.names)
        elif isinstance(node, ast.If) and isinstance(node.test, ast.UnaryOp) and isinstance(node.test.op, ast.Not):
            for n in ast.walk(node):
                if (isinstance(n, ast.Call) and getattr(n.func, "id", None) == "attach"
                        and [getattr(a, "id", None) for a in n.args] == ["__name__", "__file__"]):
                    hidden = True
                    lazy = {k: set(v) for k, v in typed_imports(str(path)).items()}
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            bound |= {a.asname or a.name.split(".")[0] for a in node.names}
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            bound |= {t.id for t in targets if isinstance(t, ast.Name)}
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            bound.add(node.name)
    return bound, typed, lazy, hidden


@pytest.mark.parametrize("package", sorted(PUBLIC_API))
def test_type_checkers_see_every_lazy_name(package):
    """Each name imported on first use is imported from the same submodule under ``if TYPE_CHECKING:``,
    so mypy and IDEs see its real type (not ``Any``), and every public name is one or the other."""
    bound, typed, lazy, _hidden = _lazy_view(package)
    assert typed == lazy, f"{package}: TYPE_CHECKING imports and lazy names differ"
    lazy_names = set().union(*lazy.values()) if lazy else set()
    unseen = set(importlib.import_module(package).__all__) - bound - lazy_names
    assert not unseen, f"{package}: public names neither bound nor lazy: {sorted(unseen)}"
    hidden = lazy_names - set(importlib.import_module(package).__all__)
    assert not hidden, f"{package}: lazy names that __all__ does not list: {sorted(hidden)}"


@pytest.mark.parametrize("package", sorted(set(PUBLIC_API) - {"regimemap.cli"}))
def test_getattr_is_hidden_from_type_checkers(package):
    """Every package's lazy names come from :func:`regimemap._lazy.attach`, called under
    ``if not TYPE_CHECKING:``: for mypy an unknown name is an error, not Any."""
    _bound, _typed, lazy, hidden = _lazy_view(package)
    assert hidden and lazy, f"{package}: no attach(...) under `if not TYPE_CHECKING:`"


def test_unknown_names_raise_attribute_error():
    import regimemap
    import regimemap.climate
    import regimemap.drawing
    import regimemap.dynamics
    import regimemap.io
    import regimemap.lifetime
    import regimemap.maps
    import regimemap.mechanics
    import regimemap.waves

    for mod in (regimemap, regimemap.drawing, regimemap.io, regimemap.maps, regimemap.dynamics,
                regimemap.lifetime, regimemap.mechanics, regimemap.waves, regimemap.climate):
        with pytest.raises(AttributeError, match=f"module '{mod.__name__}' has no attribute 'nope'"):
            mod.nope  # noqa: B018


def test_positional_wrappers_are_the_documented_ones():
    """classify(k, mu, gamma, kprime) and friends keep their positional signatures."""
    import inspect

    import regimemap

    for fn, params in (
        (regimemap.classify, ["k", "mu", "gamma", "kprime"]),
        (regimemap.label_grid, ["k_axis", "mu_axis", "gamma", "kprime"]),
        (regimemap.admissible, ["k", "mu", "gamma", "kprime", "tol"]),
        (regimemap.query_point, ["k", "mu", "gamma", "kprime", "name"]),
    ):
        assert list(inspect.signature(fn).parameters)[: len(params)] == params


LOAD_KEYWORDS = ["buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration", "crest"]


def test_every_block_description_takes_the_load_keywords():
    """The loads are keyword-only, with the report's block as default, wherever a block is described."""
    import inspect

    import regimemap
    from regimemap.maps import margin, query_points

    for fn in (regimemap.classify, regimemap.label_grid, regimemap.query_point, query_points, margin,
               regimemap.Parameters):
        params = inspect.signature(fn).parameters
        for name in LOAD_KEYWORDS:
            assert params[name].kind is inspect.Parameter.KEYWORD_ONLY, (fn, name)
        assert params["buoyancy"].default == 0.0 and params["gyration"].default is None


def test_lazy_names_are_the_objects_not_their_modules():
    """``regimemap.maps`` imports most names on first use; none may resolve to a module."""
    import importlib
    import types

    maps = importlib.import_module("regimemap.maps")
    for name in maps.__all__:
        importlib.import_module("regimemap.maps.classify")  # a submodule of the same name
        assert not isinstance(getattr(maps, name), types.ModuleType), name


def test_modules_export_the_types_of_their_results():
    """The point query exports the type it returns, the design reader the example it documents."""
    from regimemap.caisson import file as design
    from regimemap.caisson import file_example as design_example
    from regimemap.maps import point_result, query

    assert query.PointResult is point_result.PointResult
    assert design.example_design_text is design_example.example_design_text


def test_outcome_style_is_exported_by_the_drawing_package():
    """``regimemap.drawing.OutcomeStyle`` is the frozen dataclass of :mod:`regimemap.motion.figures.outcome`."""
    import dataclasses

    import regimemap.drawing
    from regimemap.motion.figures.outcome import OutcomeStyle

    assert regimemap.drawing.OutcomeStyle is OutcomeStyle
    assert dataclasses.is_dataclass(OutcomeStyle) and OutcomeStyle.__dataclass_params__.frozen
