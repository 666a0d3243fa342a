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
        "FIGSIZE", "MODE_STYLE", "MapArtists", "atlas_figure", "default_title", "draw_ambiguity",
        "draw_design_points", "draw_map", "fit_figure", "load_matplotlib", "map_figure", "new_figure", "render_map",
        "render_preset", "style_context",
        # outcome maps and motions after initiation (regimemap.dynamics)
        "OUTCOME_STYLE", "draw_outcome_map", "motion_figure", "outcome_figure",
        # a caisson's sliding over its design life (regimemap.lifetime)
        "chart_figure", "lifetime_figure",
    ],
    "regimemap.io": [
        "atomic_open", "atomic_path", "export_map", "format_result", "parse_point_spec",
        "read_points_csv", "result_row", "save_figure", "write_animation", "write_atlas",
        # simulations after initiation: pulse files, time histories, outcome maps
        "read_pulse_csv", "write_history", "write_outcome",
    ],
    "regimemap.lifetime": [
        "ADDED_MASS_COEFFICIENT", "Caisson", "Climate", "ClusterUnavailable", "DEFAULT_ERRORS",
        "DEFAULT_THRESHOLDS", "DISTRIBUTIONS", "DesignChart", "ErrorFactor", "Errors", "LifetimeModel",
        "LifetimeResult", "added_mass", "available_cores", "design_chart", "half_sine_slide",
        "lifetime_sliding", "sf_width", "wave_duration",
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


def test_unknown_names_raise_attribute_error():
    import regimemap
    import regimemap.drawing
    import regimemap.io

    for mod in (regimemap, regimemap.drawing, regimemap.io):
        with pytest.raises(AttributeError, match="no attribute 'nope'"):
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
