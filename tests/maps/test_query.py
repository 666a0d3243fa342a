"""Point queries: physics from the solver, admissible sets, and exact margins."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from regimemap import Mode, Parameters, classify
from regimemap.maps.file_points import DesignPoint
from regimemap.maps.query import (
    HYPOTHESES_OF_MODE,
    Crossing,
    margin,
    query_point,
    query_points,
)
from regimemap.maps.record_tables import CSV_COLUMNS, format_result, result_row
from regimemap.mechanics.solver import Hypothesis, admissible, solve

from .._sweep import sample_points, sweep


def _modes_along(queries: list) -> list[Mode]:
    """The mode of the point of each ``(var, r, value)`` in ``queries``: the result ``r``'s point
    with its ``var`` ("k" or "mu") set to ``value`` -- one call of classify for all (it is
    pointwise: the labels of one call per point)."""
    k = np.array([v if var == "k" else r.k for var, r, v in queries])
    mu = np.array([v if var == "mu" else r.mu for var, r, v in queries])
    gamma = np.array([r.gamma for _, r, _ in queries])
    kprime = np.array([r.kprime for _, r, _ in queries])
    return [Mode(int(c)) for c in classify(k, mu, gamma, kprime)]


def _random_points(n_per: int = 25, n_kprime: int = 9) -> list[DesignPoint]:
    pts = []
    for g, kp in sweep(n_kprime):
        k, mu = sample_points(g, kp, n_per, seed=int(1000 * g + 100 * kp) % 4099)
        pts += [DesignPoint(float(a), float(b), "", g, kp) for a, b in zip(k, mu)]
    return pts


@pytest.fixture(scope="module")
def results():
    return query_points(_random_points())


@pytest.mark.slow
def test_mode_equals_classify(results):
    for r in results:
        assert r.mode == Mode(int(classify(r.k, r.mu, r.gamma, r.kprime)))


@pytest.mark.deep
def test_physics_equals_solver_of_chosen_hypothesis(results):
    for r in results:
        assert r.hypothesis in HYPOTHESES_OF_MODE[r.mode]
        s = solve(r.hypothesis, r.k, r.mu, r.gamma, r.kprime)
        for key in ("fx", "fy", "xi", "xdd", "ydd", "thdd"):
            assert getattr(r, key) == pytest.approx(float(getattr(s, key)), abs=1e-12), key
        if r.hypothesis.sigma == 0:
            assert r.slip is None
        else:
            assert r.slip == pytest.approx(float(s.slip), abs=1e-12)
        if r.hypothesis.contact == "full":
            assert r.lift is None
        else:
            assert r.lift == pytest.approx(float(s.lift), abs=1e-12)


@pytest.mark.slow
def test_chosen_hypothesis_is_admissible(results):
    for r in results:
        assert r.hypothesis_admissible
        assert bool(solve(r.hypothesis, r.k, r.mu, r.gamma, r.kprime).ok)


@pytest.mark.slow
def test_admissible_set_equals_solver_and_contains_mode(results):
    # the solver on every point at once (it is pointwise)
    adm = admissible(*(np.array([getattr(r, a) for r in results]) for a in ("k", "mu", "gamma", "kprime")))
    for i, r in enumerate(results):
        assert set(r.admissible) == {m for m, ok in adm.items() if bool(ok[i])}
        assert r.mode in r.admissible
        # Section 4.7: the chosen mode is the first admissible one in PRIORITY order
        assert r.admissible[0] == r.mode


@pytest.mark.slow
def test_margins_are_exact(results):
    """The mode holds strictly inside the margin and differs at the boundary found."""
    checked = 0
    # the labels along the margins, gathered and classified at once: (var, r, value) per query
    at, inside, beyond = [], [], []
    for r in results:
        for m in (r.margin_k, r.margin_mu):
            x = m.value
            for c in (m.up, m.down):
                if c is None:
                    continue
                checked += 1
                assert (c.at > x) if c.direction == "up" else (c.at < x)
                assert c.delta == pytest.approx(abs(c.at - x))
                at.append((m.variable, r, c.at))
                # just inside, and along the whole way, the mode is the point's own
                for t in (0.0, 0.25, 0.5, 0.9, 1.0 - 1e-9):
                    inside.append(((m.variable, r, x + (c.at - x) * t), (c, t)))
                # just beyond, the mode is the reported one (or, for an isolated
                # boundary point, the mode at the boundary)
                b = c.at + (c.at - x) * 1e-9
                if b >= 0.0:
                    beyond.append(((m.variable, r, b), len(at) - 1, c))
    assert checked > 1000
    mode_at = _modes_along(at)
    for (_, r, _), mode in zip(at, mode_at, strict=True):
        assert mode != r.mode
    for ((var, r, _), (c, t)), mode in zip(inside, _modes_along([q for q, _ in inside]), strict=True):
        assert mode == r.mode, (var, c, t)
    for ((_, _, _), i, c), mode in zip(beyond, _modes_along([q for q, _, _ in beyond]), strict=True):
        assert c.to in (mode, mode_at[i])


@pytest.mark.slow
def test_no_change_means_none_far_away(results):
    queries = []
    for r in results:
        for m in (r.margin_k, r.margin_mu):
            if m.up is None:
                queries += [(m.variable, r, v) for v in (m.value * 1.01 + 1e-3, 10 * m.value + 1.0, 1e3, 1e7)]
            if m.down is None and m.value > 0:
                queries += [(m.variable, r, v) for v in (0.0, 0.5 * m.value, 0.999 * m.value)]
    for (var, r, v), mode in zip(queries, _modes_along(queries), strict=True):
        assert mode == r.mode, (var, v)


def test_nearest_and_relative(results):
    for r in results:
        for m in (r.margin_k, r.margin_mu):
            options = [c for c in (m.up, m.down) if c is not None]
            if not options:
                assert m.nearest is None and m.relative is None
                continue
            assert m.nearest.delta == min(c.delta for c in options)
            if m.value > 0:
                assert m.relative == pytest.approx(m.nearest.delta / m.value)


def test_known_margin_above_c():
    # gamma 3, k' 0.4: at mu = 0.2 the slide region ends on the right at the line
    # CD, mu = 1/3 - 0.4 k  ->  k = 1/3; to the left at OA, k = mu = 0.2.
    mk, mm = margin(0.3, 0.2, 3.0, 0.4)
    assert mk.up.at == pytest.approx(1.0 / 3.0, rel=1e-12)
    assert mk.up.to is Mode.SRO_MINUS
    assert mk.down.at == pytest.approx(0.2, rel=1e-12)
    assert mk.down.to is Mode.RE
    assert mk.nearest is mk.up
    assert mk.relative == pytest.approx((1.0 / 3.0 - 0.3) / 0.3, rel=1e-9)
    # along mu at k = 0.3: SL down to 0 (no change), CD at mu = 1/3 - 0.12
    assert mm.down is None
    assert mm.up.at == pytest.approx(1.0 / 3.0 - 0.12, rel=1e-12)


@pytest.mark.parametrize("k,mu", [(0.3, 1e100), (1e100, 0.5), (1e100, 1e100), (0.5 * 1e100, 0.6)])
def test_margins_at_the_largest_k_and_mu_probe_no_further(k, mu):
    # the probe beyond the last root (2 x + 1) stops at MAX_VALUE: it used to be refused there
    from regimemap.mechanics.validation import MAX_VALUE

    r = query_point(k, mu, 3.0, 0.4)
    for m in (r.margin_k, r.margin_mu):
        for c in (m.up, m.down):
            assert c is None or 0.0 <= c.at <= MAX_VALUE
    assert r.mode == int(classify(k, mu, 3.0, 0.4))


@pytest.mark.slow
def test_margin_at_zero():
    r = query_point(0.0, 0.0, 3.0, 0.4)
    assert r.mode is Mode.RE
    assert r.margin_k.down is None and r.margin_mu.down is None
    up = r.margin_k.up
    assert up is not None and up.relative is None  # relative change from 0 is undefined
    assert up.delta < 1e-300  # any push at mu = 0 slides the block
    assert up.to is Mode.SL
    assert r.margin_mu.up is None  # with k = 0 nothing ever moves
    assert r.on_boundary and r.chosen_by == "boundary"
    d = r.as_dict()
    assert d["margin"]["k"]["up"]["relative"] is None


def test_point_on_boundary_has_zero_margin():
    # on OA (mu = k) below A: the point is at rest, a hair less friction slides it
    r = query_point(0.2, 0.2, 3.0, 0.4)
    assert r.mode is Mode.RE
    assert r.margin_mu.down.delta <= 1e-15
    assert r.margin_mu.down.to is Mode.SL
    assert set(r.admissible) == {Mode.RE, Mode.SL}
    assert r.on_boundary and not r.nonunique


def test_nonunique_point_below_c():
    g, kp = 3.0, -0.6
    p = Parameters(g, kp)
    r = query_point(3.5, 2.3, g, kp)
    assert r.mu > p.mu_Bprime
    assert set(r.admissible) == {Mode.SL, Mode.RO, Mode.SRO_MINUS}
    assert r.mode is Mode.SL and r.chosen_by == "Section 4.7" and r.nonunique


def test_known_physics_rock():
    # rocking about O: xi = -1, the lift of O' is -2 x (-thdd) = 2 thdd, no slip
    r = query_point(0.5, 0.8, 3.0, 0.4)
    assert r.hypothesis is Hypothesis.ROCK_O
    assert r.xi == pytest.approx(-1.0)
    assert r.thdd > 0 and r.lift == pytest.approx(2 * r.thdd)
    assert r.slip is None
    # X + gamma T = 0: the pivot O does not slide
    assert r.xdd + 3.0 * r.thdd == pytest.approx(0.0, abs=1e-12)


def test_as_dict_json_round_trip():
    r = query_point(2.0, 0.1, 3.0, -0.6, name="caisson")
    d = json.loads(json.dumps(r.as_dict(), allow_nan=False))
    for key in ("mode", "fx", "fy", "xi", "xdd", "ydd", "thdd", "slip", "case", "margin",
                "admissible", "k", "mu", "gamma", "kprime", "name"):
        assert key in d
    assert d["mode"] == "SRO'-" and d["name"] == "caisson" and d["case"] == "delta>=0"
    assert d["slip"] == pytest.approx(r.slip)


def test_thresholds_none_when_infinite():
    d = query_point(1.0, 0.5, 2.0, -1.0).as_dict()
    assert d["thresholds"]["k_A"] is None  # k' = -1: no point A


def test_query_points_defaults_and_own_parameters():
    pts = [DesignPoint(0.5, 0.8, "a"), DesignPoint(3.5, 2.3, "b", 3.0, -0.6),
           DesignPoint(0.1, 0.05, "c", 2.0, None)]
    res = query_points(pts, gamma=3.0, kprime=0.4)
    assert [(r.name, r.gamma, r.kprime) for r in res] == [
        ("a", 3.0, 0.4), ("b", 3.0, -0.6), ("c", 2.0, 0.4)]
    assert [r.mode.label for r in res] == ["RO", "SL", "SL"]
    # plain (k, mu) pairs work too
    assert query_points([(0.5, 0.8)], gamma=3.0, kprime=0.4)[0].mode is Mode.RO


def test_query_points_missing_parameters_named():
    with pytest.raises(ValueError, match=r"point 2 \('b'\) has no gamma"):
        query_points([DesignPoint(1, 1, "a", 1.0, 0.0), DesignPoint(1, 1, "b")], kprime=0.0)
    with pytest.raises(ValueError, match="no kprime"):
        query_points([DesignPoint(1, 1)], gamma=1.0)


@pytest.mark.parametrize("kwargs,match", [
    (dict(k=-1, mu=1, gamma=1, kprime=0), "k must be"),
    (dict(k=1, mu=math.nan, gamma=1, kprime=0), "mu must be"),
    (dict(k=1, mu=1, gamma=0, kprime=0), "gamma must be"),
    (dict(k=1, mu=1, gamma=1, kprime=1.5), r"kprime must be a number in \[-1, 1\]"),
])
def test_query_point_rejects_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        query_point(**kwargs)


def test_result_row_has_all_columns():
    r = query_point(0.5, 0.8, 3.0, 0.4, name="x")
    row = result_row(r)
    assert list(row) == list(CSV_COLUMNS)
    assert row["mode"] == "RO" and row["slip"] == "" and row["name"] == "x"
    assert float(row["margin_k"]) == pytest.approx(r.margin_k.relative)


@pytest.mark.slow
def test_vectorised_blocks_agree_with_single_queries():
    pts = _random_points(3, 5)[:120]
    many = query_points(pts)
    for pt, r in zip(pts[::7], many[::7]):
        one = query_point(pt.k, pt.mu, pt.gamma, pt.kprime)
        assert one.as_dict() == r.as_dict()


def test_crossing_as_dict():
    c = Crossing("up", 2.0, 1.0, 1.0, Mode.RO)
    assert c.as_dict() == {"direction": "up", "at": 2.0, "delta": 1.0, "relative": 1.0, "to": "RO"}


def test_unsolvable_system_reported_not_invented(monkeypatch):
    """Where the solver cannot solve the chosen hypothesis, the physics is None, not garbage."""
    import dataclasses

    import regimemap.maps.query as q

    real = q.solve

    def singular_rock(h, *args, **kw):
        r = real(h, *args, **kw)
        if h is Hypothesis.ROCK_O:
            r = dataclasses.replace(r, solvable=np.zeros_like(r.solvable), ok=np.zeros_like(r.ok))
        return r

    monkeypatch.setattr(q, "solve", singular_rock)
    r = q.query_point(0.5, 0.8, 3.0, 0.4)
    assert r.mode is Mode.RO and not r.solvable
    assert all(math.isnan(getattr(r, key)) for key in ("fx", "fy", "xi", "xdd", "ydd", "thdd"))
    assert r.lift is None and r.admissible == () and r.chosen_by == "map only"
    d = json.loads(json.dumps(r.as_dict(), allow_nan=False))
    assert d["fx"] is None and d["solvable"] is False
    text = format_result(r)
    assert "singular" in text and "fx    =         n/a" in text
    # the margin does not depend on the solver
    assert r.margin_k.down.to is Mode.RE
