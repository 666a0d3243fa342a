"""run_query: design points classified, as classify computes them; io writes the record."""

from __future__ import annotations

import csv
import io
import json

import pytest

from regimemap.maps.points import DesignPoint
from regimemap.maps.query import query_points
from regimemap.maps.record_tables import results_text
from regimemap.workflows import QueryRecord, run_query


def test_the_record_holds_what_query_points_returns():
    pts = [DesignPoint(0.5, 0.8, "a"), DesignPoint(3.5, 2.3, "b", gamma=3.0, kprime=-0.6)]
    rec = run_query(pts, gamma=3.0, kprime=0.4)
    assert isinstance(rec, QueryRecord) and rec.points == tuple(pts)
    assert list(rec.results) == query_points(pts, gamma=3.0, kprime=0.4)
    assert rec.count == 2 and rec.modes == tuple(r.mode.label for r in rec.results)
    assert rec.notices == ()


def test_loads_are_the_default_of_every_point():
    rec = run_query([(0.28, 0.6)], gamma=0.7, kprime=-0.02, buoyancy=0.32, uplift_ratio=0.52)
    assert rec.loads == {"buoyancy": 0.32, "uplift_ratio": 0.52}
    assert rec.results[0].loads and rec.results[0].chosen_by


def test_a_point_without_gamma_is_an_error_naming_it():
    with pytest.raises(ValueError, match=r"point 1 \('x'\) has no gamma"):
        run_query([DesignPoint(0.5, 0.8, "x")], kprime=0.4)


def test_results_text_as_csv_and_json():
    rec = run_query([DesignPoint(0.5, 0.8, "a"), DesignPoint(0.1, 0.05, "c")], gamma=3.0,
                    kprime=0.4)
    rows = list(csv.DictReader(io.StringIO(results_text(rec.results, False))))
    assert [r["name"] for r in rows] == ["a", "c"] and rows[0]["mode"] == rec.modes[0]
    doc = json.loads(results_text(rec.results, True))
    assert doc["count"] == 2 and [p["name"] for p in doc["points"]] == ["a", "c"]
