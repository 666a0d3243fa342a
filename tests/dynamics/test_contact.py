"""The contact problem of one step (regimemap.dynamics.contact), state by state, without a time loop.

From rest the velocity problem is the onset's acceleration problem times the step h, so each
state's velocity over h is checked against the independent equations-of-motion solver of
regimemap.mechanics (and its mode against regimemap.classify); rocking, impacts and flight are
checked against their closed forms.
"""

from __future__ import annotations

import numpy as np
import pytest

import regimemap
from regimemap.dynamics import Block
from regimemap.dynamics.contact import PIVOT_O, PIVOT_P, ROCKS, SLIDES, Arms, Contact, Phase, corner_impact
from regimemap.mechanics.modes import Mode
from regimemap.mechanics.solver import Hypothesis, solve

G = 9.81
H_STEP = 1e-3

#: The hypothesis of the mechanics solver that a state from rest under a push towards O is.
HYPOTHESIS = {
    Phase.RE: Hypothesis.REST, Phase.SL: Hypothesis.SLIDE_LEFT, Phase.RO: Hypothesis.ROCK_O,
    Phase.SRO_MINUS: Hypothesis.SLIDE_ROCK_O_LEFT, Phase.SRO_PLUS: Hypothesis.SLIDE_ROCK_O_RIGHT,
    Phase.SRO_PRIME_MINUS: Hypothesis.SLIDE_ROCK_O_PRIME_LEFT, Phase.FLIGHT: Hypothesis.LIFT_OFF,
}


def contact_at(blk: Block, theta: float, *, act_O: bool = True, act_P: bool = True,
               h: float = H_STEP) -> Contact:
    """The contact problem of one run of ``blk`` turned by ``theta``."""
    B = np.atleast_1d(np.asarray(blk.B, dtype=np.float64))
    H = np.atleast_1d(blk.H)
    J = np.atleast_1d(blk.gyration2) * B * B
    return Contact(Arms.at(np.full(B.shape, theta), B, H), np.full(B.shape, act_O),
                   np.full(B.shape, act_P), np.atleast_1d(np.asarray(blk.mu, dtype=np.float64)), J,
                   np.full(B.shape, 1e-10 * G * h))


def from_rest(blk: Block, k: float, h: float = H_STEP):
    """The state of the first step from rest on the base under a push k (loads of the block)."""
    B = float(np.asarray(blk.B))
    H = float(blk.H)
    J = float(blk.gyration2) * B * B
    lift = float(np.asarray(blk.uplift)) + float(np.asarray(blk.uplift_ratio)) * k
    fx = -G * k
    fy = G * (float(np.asarray(blk.buoyancy)) + lift - 1.0)
    tau = (G / J) * (k * float(np.asarray(blk.kprime)) * H + float(np.asarray(blk.uplift_arm)) * B * lift)
    state = contact_at(blk, 0.0, h=h).solve(np.array([h * fx]), np.array([h * fy]), np.array([h * tau]))
    assert not state.unresolved.any()
    return state


def onset(blk: Block, k: float, hyp: Hypothesis):
    """The mechanics solver's onset of ``hyp`` for ``blk`` under k."""
    return solve(hyp, k, float(np.asarray(blk.mu)), float(np.asarray(blk.gamma)),
                 float(np.asarray(blk.kprime)), buoyancy=float(np.asarray(blk.buoyancy)),
                 uplift=float(np.asarray(blk.uplift)), uplift_ratio=float(np.asarray(blk.uplift_ratio)),
                 uplift_arm=float(np.asarray(blk.uplift_arm)),
                 gyration=None if blk.i2 is None else float(np.sqrt(blk.i2)))


def assert_onset_accelerations(blk: Block, k: float, state, h: float = H_STEP) -> None:
    """The state's velocity over h is the acceleration of its hypothesis at the onset."""
    r = onset(blk, k, HYPOTHESIS[Phase(int(state.code[0]))])
    assert bool(r.ok), "the mechanics solver does not admit the state"
    B = float(np.asarray(blk.B))
    assert state.vx[0] / h == pytest.approx(float(r.xdd) * G, rel=1e-9, abs=1e-9)
    assert state.vy[0] / h == pytest.approx(float(r.ydd) * G, rel=1e-9, abs=1e-9)
    assert state.om[0] / h == pytest.approx(float(r.thdd) * G / B, rel=1e-9, abs=1e-9)


# -- from rest: the states of the onset ---------------------------------------------------------------

def test_rest_under_a_small_push_is_exactly_still() -> None:
    blk = Block(B=0.2, gamma=3.0, mu=0.5)  # k = 0.2 < tan(alpha) = 1/3 and < mu
    state = from_rest(blk, 0.2)
    assert state.code[0] == Phase.RE
    assert state.vx[0] == 0.0 and state.vy[0] == 0.0 and state.om[0] == 0.0
    assert bool(onset(blk, 0.2, Hypothesis.REST).ok)


def test_rest_also_absorbs_a_small_downward_velocity() -> None:
    # chattering rest: the block lands flat at 1 mm/s and stops, both corners stuck
    blk = Block(B=0.2, gamma=3.0, mu=0.5)
    c = contact_at(blk, 0.0)
    state = c.solve(np.array([0.0]), np.array([-1e-3]), np.array([0.0]))
    assert state.code[0] == Phase.RE
    assert state.vx[0] == 0.0 and state.vy[0] == 0.0 and state.om[0] == 0.0


@pytest.mark.parametrize("k, mu", [(0.5, 0.3), (0.35, 0.2), (0.9, 0.6)])
def test_pure_slide_has_the_closed_form_acceleration(k: float, mu: float) -> None:
    blk = Block(B=1.0, gamma=0.5, mu=mu)  # squat: tan(alpha) = 2, never rocks here
    state = from_rest(blk, k)
    assert state.code[0] == Phase.SL
    assert state.vy[0] == 0.0 and state.om[0] == 0.0
    assert state.vx[0] / H_STEP == pytest.approx(-G * (k - mu), rel=1e-12)  # x'' = -(k - mu) g
    assert_onset_accelerations(blk, k, state)


def test_slide_to_the_right_under_a_pull() -> None:
    blk = Block(B=1.0, gamma=0.5, mu=0.3)
    state = from_rest(blk, -0.5)
    assert state.code[0] == Phase.SL
    assert state.vx[0] / H_STEP == pytest.approx(G * (0.5 - 0.3), rel=1e-12)


# (gamma, kprime, k, mu): one point inside each mode of the report's map (regimemap.classify)
ONSET_POINTS = {
    Mode.RE: [(2.0, 0.0, 0.2, 0.3), (3.0, -0.5, 0.3, 2.0)],
    Mode.SL: [(2.0, 0.0, 0.5, 0.3), (3.0, 0.5, 0.2, 0.1)],
    Mode.RO: [(2.0, 0.0, 0.8, 1.0), (3.0, 0.5, 1.2, 2.0)],
    Mode.SRO_MINUS: [(2.0, 0.0, 1.2, 0.6), (3.0, 0.0, 2.0, 0.6)],
    Mode.SRO_PLUS: [(3.0, 1.0, 1.2, 0.1), (3.0, 1.0, 2.0, 0.1)],
    Mode.SRO_PRIME_MINUS: [(2.0, -0.5, 2.0, 0.1), (2.0, -0.5, 3.0, 0.3)],
}


@pytest.mark.parametrize("mode, point", [(m, p) for m, pts in ONSET_POINTS.items() for p in pts],
                         ids=lambda v: v.label if isinstance(v, Mode) else str(v))
def test_each_onset_state_is_the_mode_of_classify_with_its_accelerations(
        mode: Mode, point: tuple[float, float, float, float]) -> None:
    gamma, kprime, k, mu = point
    assert int(regimemap.classify(k, mu, gamma, kprime)) == mode
    blk = Block(B=0.5, gamma=gamma, mu=mu, kprime=kprime)
    state = from_rest(blk, k)
    assert int(state.code[0]) == int(mode), Phase(int(state.code[0])).label
    assert_onset_accelerations(blk, k, state)


@pytest.mark.parametrize("loads, k", [
    ({"buoyancy": 0.3}, 0.6), ({"buoyancy": 0.2, "uplift": 0.15, "kprime": 0.4}, 0.5),
    ({"buoyancy": 0.1, "uplift": 0.1, "uplift_ratio": 0.3, "uplift_arm": 0.5, "kprime": -0.3}, 0.9),
    ({"buoyancy": 0.35, "uplift_ratio": 0.25, "kprime": -0.1, "i2": 0.6}, 0.4),
])
def test_loaded_onset_states_are_admissible_with_their_accelerations(loads: dict[str, float],
                                                                     k: float) -> None:
    blk = Block(B=2.0, gamma=1.5, mu=0.6, **loads)
    state = from_rest(blk, k)
    assert_onset_accelerations(blk, k, state)


@pytest.mark.parametrize("loads, k", [
    ({"buoyancy": 0.4, "uplift": 0.7, "uplift_arm": 0.0}, 0.3),  # 0.4 + 0.7 > 1, the uplift through C
    ({"buoyancy": 0.5, "uplift_ratio": 3.0}, 0.5),  # 0.5 + 1.5 > 1: lifts both corners despite its moment
])
def test_flight_when_the_loads_exceed_the_weight(loads: dict[str, float], k: float) -> None:
    blk = Block(B=1.0, gamma=1.0, mu=0.6, **loads)
    J = float(blk.gyration2)
    lift = loads.get("uplift", 0.0) + loads.get("uplift_ratio", 0.0) * k
    v_free = (np.array([-G * k * H_STEP]), np.array([G * (loads["buoyancy"] + lift - 1.0) * H_STEP]),
              np.array([(G / J) * float(np.asarray(blk.uplift_arm)) * lift * H_STEP]))
    state = contact_at(blk, 0.0).solve(*v_free)
    assert state.code[0] == Phase.FLIGHT
    # no reaction: the free velocity, to the last bit
    assert state.vx[0] == v_free[0][0] and state.vy[0] == v_free[1][0] and state.om[0] == v_free[2][0]
    assert_onset_accelerations(blk, k, state)


# -- in motion: rocking and impacts -------------------------------------------------------------------

def rotation_about(corner: str, arms: Arms, om: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The velocity of C turning at ``om`` about the corner (arms from C): v = om z x (-r)."""
    rx, ry = (arms.xO, arms.yO) if corner == "O" else (arms.xP, arms.yP)
    return om * ry, -om * rx, np.full(rx.shape, om)


@pytest.mark.parametrize("theta, om", [(0.05, 0.4), (0.12, -0.8), (0.2, 0.1)])
@pytest.mark.parametrize("i2", [None, 2.0])
def test_rocking_about_O_has_the_closed_form_angular_acceleration(theta: float, om: float,
                                                                  i2: float | None) -> None:
    # free rocking about O (theta > 0): theta'' = -p^2 sin(alpha - theta), p^2 = m g R / I_O
    blk = Block(B=0.3, gamma=3.0, mu=5.0, i2=i2)
    c = contact_at(blk, theta, act_P=False)
    vx, vy, omv = rotation_about("O", c.arms, om)
    state = c.solve(vx, vy - G * H_STEP, omv)
    assert state.code[0] == Phase.RO
    p2, alpha = float(blk.p) ** 2, float(blk.alpha)
    assert (state.om[0] - om) / H_STEP == pytest.approx(-p2 * np.sin(alpha - theta), rel=1e-9)
    # O stays where it is
    a = c.arms
    assert state.vy[0] + a.xO[0] * state.om[0] == pytest.approx(0.0, abs=1e-15)
    assert state.vx[0] - a.yO[0] * state.om[0] == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("theta, om", [(-0.05, -0.4), (-0.12, 0.8)])
def test_rocking_about_O_prime_is_the_mirror(theta: float, om: float) -> None:
    blk = Block(B=0.3, gamma=3.0, mu=5.0)
    c = contact_at(blk, theta, act_O=False)
    vx, vy, omv = rotation_about("O'", c.arms, om)
    state = c.solve(vx, vy - G * H_STEP, omv)
    assert state.code[0] == Phase.RO_PRIME
    p2, alpha = float(blk.p) ** 2, float(blk.alpha)
    assert (state.om[0] - om) / H_STEP == pytest.approx(p2 * np.sin(alpha + theta), rel=1e-9)


@pytest.mark.parametrize("gamma, i2", [(2.0, None), (3.0, None), (5.0, None), (3.0, 2.0)])
def test_plastic_corner_impact_is_housners_ratio(gamma: float, i2: float | None) -> None:
    # rocking back about O onto the base: O' hits, and the block rocks on about O'
    blk = Block(B=0.3, gamma=gamma, mu=5.0, i2=i2)
    c = contact_at(blk, 0.0)
    v = rotation_about("O", c.arms, -1.0)
    plastic = c.solve(*v)
    assert plastic.code[0] == Phase.RO_PRIME
    assert plastic.om[0] == pytest.approx(float(blk.housner_ratio) * -1.0, rel=1e-12)
    # the corner impact map: restitution r instead of Housner's ratio
    for r in (0.5, 0.8):
        ratio = np.array([r / float(blk.housner_ratio)])
        after = corner_impact(c, v, np.array([False]), np.array([True]), ratio)
        assert after[2][0] == pytest.approx(-r, rel=1e-12)
        assert after[1][0] + c.arms.xP[0] * after[2][0] == pytest.approx(0.0, abs=1e-14)


def test_corner_impact_never_adds_energy_and_keeps_flat_landings_plastic() -> None:
    blk = Block(B=0.3, gamma=3.0, mu=5.0)
    c = contact_at(blk, 0.0)
    J = float(blk.gyration2) * 0.09
    v = rotation_about("O", c.arms, -1.0)
    ke0 = v[0][0] ** 2 + v[1][0] ** 2 + J * v[2][0] ** 2
    after = corner_impact(c, v, np.array([False]), np.array([True]), np.array([50.0]))
    ke1 = after[0][0] ** 2 + after[1][0] ** 2 + J * after[2][0] ** 2
    assert ke1 == pytest.approx(ke0, rel=1e-12)  # capped at the energy before
    flat = (np.array([0.0]), np.array([-0.5]), np.array([0.0]))
    landed = corner_impact(c, flat, np.array([True]), np.array([True]), np.array([2.0]))
    assert landed[0][0] == 0.0 and landed[1][0] == 0.0 and landed[2][0] == 0.0


# -- the tables and the batch -------------------------------------------------------------------------

def test_state_tables_follow_the_phases() -> None:
    for ph in Phase:
        label = ph.label
        assert SLIDES[ph] == (label == "SL" or label.startswith("SRO"))
        assert ROCKS[ph] == (label not in ("RE", "SL"))
        assert PIVOT_O[ph] == (label in ("RO", "SRO-", "SRO+"))
        assert PIVOT_P[ph] == (label in ("RO'", "SRO'-", "SRO'+"))
        assert Mode(int(ph)).label == label or ph is Phase.FLIGHT


def test_arms_at_rest_are_the_corners() -> None:
    a = Arms.at(np.zeros(1), np.array([0.2]), np.array([0.6]))
    assert (a.xO[0], a.yO[0], a.xP[0], a.yP[0]) == (-0.2, -0.6, 0.2, -0.6)


def test_a_batch_of_states_is_solved_run_by_run() -> None:
    """Runs in different states in one call give what each gives alone (the batch is elementwise)."""
    cases = [(Block(B=0.2, gamma=3.0, mu=0.5), 0.2), (Block(B=0.2, gamma=0.5, mu=0.3), 0.5),
             (Block(B=0.2, gamma=2.0, mu=1.0), 0.8), (Block(B=0.2, gamma=2.0, mu=0.6), 1.2)]
    alone = [from_rest(b, k) for b, k in cases]
    blk = Block(B=0.2, gamma=np.array([3.0, 0.5, 2.0, 2.0]), mu=np.array([0.5, 0.3, 1.0, 0.6]))
    k = np.array([k for _, k in cases])
    B, H = 0.2, blk.H
    J = blk.gyration2 * B * B
    c = Contact(Arms.at(np.zeros(4), np.full(4, B), H), np.ones(4, bool), np.ones(4, bool),
                np.asarray(blk.mu, dtype=np.float64), J, np.full(4, 1e-10 * G * H_STEP))
    both = c.solve(-G * k * H_STEP, np.full(4, -G * H_STEP), np.zeros(4))
    assert [Phase(int(s.code[0])) for s in alone] == [Phase(int(x)) for x in both.code]
    assert [s.vx[0] for s in alone] == both.vx.tolist()
    assert [s.om[0] for s in alone] == both.om.tolist()
    assert sorted({Phase(int(x)).label for x in both.code}) == ["RE", "RO", "SL", "SRO-"]
