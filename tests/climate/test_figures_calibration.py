"""The coverage benchmark's figure: a row per method, a panel per level, a point per case and period."""

from __future__ import annotations

import pytest

from regimemap.climate.figures_calibration import calibration_figure


def _method(coverage: float) -> dict:
    cases = []
    for xi in (-0.3, 0.0):
        for years in (10.0, 40.0):
            level = {"coverage": coverage, "se": 0.02}
            cases.append({"xi": xi, "years": years,
                          "periods": {p: {"90": dict(level), "95": dict(level)} for p in ("10", "50", "100")}})
    return {"cases": cases, "records_per_case": 300}


@pytest.mark.render
def test_a_row_per_method_and_a_point_per_case_and_period():
    fig = calibration_figure({"bootstrap": _method(0.75), "posterior": _method(0.9)})
    labels = sorted(ax.get_label() for ax in fig.axes)
    assert labels == ["bootstrap 90", "bootstrap 95", "posterior 90", "posterior 95"]
    ax = next(a for a in fig.axes if a.get_label() == "bootstrap 90")
    points = [line for line in ax.lines if line.get_marker() in ("o", "s", "^")]
    assert len(points) == 3 and all(len(line.get_ydata()) == 4 for line in points)
    assert {float(y) for line in points for y in line.get_ydata()} == {75.0}
    assert ax.get_ylim()[0] <= 71.0  # the lowest bar (75 - 2 x 2 points) is in view


@pytest.mark.render
def test_an_unknown_method_is_an_error():
    with pytest.raises(ValueError, match="profile"):
        calibration_figure({"posterior": _method(0.9)}, ["profile"])
    with pytest.raises(ValueError, match="no interval method"):
        calibration_figure({})
