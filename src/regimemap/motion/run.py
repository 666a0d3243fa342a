"""One run of a block under a force pulse, past initiation: :func:`run_simulation` and its record.

The run's inputs come from plain objects (a :class:`~regimemap.dynamics.Block` and a
:class:`~regimemap.dynamics.Pulse`), from the options of ``regimemap simulate`` (a mapping
named as :data:`regimemap.dynamics.limits.INPUT_LIMITS`), or from a caisson's design file
(its equivalent block under its design wave, :mod:`regimemap.dynamics.design_wave`).  The
:class:`SimulationRecord` holds them, the quantities a designer checks (p, alpha, H,
Housner's ratio and the impact ratio used, the pulse's peak, duration and frequency), the
design file's requirements (Goda's safety factors), the warnings as
:class:`~regimemap.records.notices.Notice` and the :class:`~regimemap.dynamics.Simulation`.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from ..records.notices import Notice
from .file import OptionError
from .record import SimulationRecord

if TYPE_CHECKING:  # pragma: no cover
    from ..caisson.file import Design
    from ..dynamics import Block, Pulse, Simulation
    from ..records.checks import Check
    from ..waves import CaissonAnalysis

__all__ = ["IMPLAUSIBLE", "STILL_MOVING", "SimulationRecord", "UNRESOLVED", "run_simulation"]

#: The codes of the notices of a run.
IMPLAUSIBLE = "implausible-value"
STILL_MOVING = "still-moving"
UNRESOLVED = "unresolved-contact"

#: The block's options and their values when not given.
_OPTION_DEFAULTS: dict[str, Any] = {
    "gamma": None, "half_width": None, "kprime": None, "mu": None, "pulse": None, "k_peak": None,
    "duration": None, "pulse_file": None, "buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0,
    "uplift_arm": 1.0 / 3.0, "gyration": None}
#: The inputs of a record, in order.
_INPUTS = ("gamma", "half_width", "kprime", "mu", "pulse", "k_peak", "duration", "pulse_file", "restitution",
           "buoyancy", "uplift", "uplift_ratio", "uplift_arm", "gyration", "design", "min_rotation")


def run_simulation(block_or_design: Block | Mapping[str, Any] | str | os.PathLike[str],
                   pulse: Pulse | None = None, *, restitution: float | None = None, history: bool = False,
                   min_rotation: float = 0.0, strict: bool = False) -> SimulationRecord:
    """Simulate one block under one force pulse, from rest, past initiation.

    Parameters
    ----------
    block_or_design : Block, mapping, str or path
        The block (with ``pulse``); or the options of ``regimemap simulate`` by name
        (``gamma``, ``half_width``, ``mu``, ``kprime``, ``pulse``, ``k_peak``, ``duration`` or
        ``pulse_file``, ``buoyancy``, ``uplift``, ``uplift_ratio``, ``uplift_arm``,
        ``gyration``; each range-checked already, :data:`regimemap.dynamics.limits.INPUT_LIMITS`);
        or the path of a caisson's design file: its equivalent block under its design wave
        Hmax, a half-sine of peak k = P/(m g) lasting tau0 = (0.5 - Hmax/(8 h)) T1/3
        (Shimosako & Takahashi 1999; :func:`regimemap.dynamics.design_wave.design_wave_run`).
    pulse : Pulse, optional
        The force pulse of a block (not with options or a design file).
    restitution : float, optional
        Ratio of a rocking impact; None is Housner's plastic impact.
    history : bool
        Whether to keep the run's time history (for a file, a plot, an animation).
    min_rotation : float
        Count rocking only above this largest rotation (degrees).
    strict : bool
        Refuse a design file's implausible values (likely unit slips) instead of warning.

    Returns
    -------
    SimulationRecord

    Raises
    ------
    OptionError
        Options that do not go together, a bad pulse or design file, an implausible value
        under ``strict``, a run over the step limit: naming the option concerned
        (``--duration``, ``--design`` ...).  Its ``notices`` are the warnings found before.
    """
    from ..dynamics import simulate
    from ..dynamics.limits import check_run_steps

    design: str | None = None
    numbers: dict[str, float] | None = None
    checks: tuple[Check, ...] = ()
    notices: list[Notice] = []
    if isinstance(block_or_design, (str, os.PathLike)):
        design = os.fspath(block_or_design)
        block, pls, inputs, numbers, checks = _design_run(design, strict, notices)
    elif isinstance(block_or_design, Mapping):
        block, pls, inputs = _options_run({**_OPTION_DEFAULTS, **block_or_design})
    else:
        if pulse is None:
            raise TypeError("run_simulation(block, pulse): give the pulse of the block")
        block, pls, inputs = block_or_design, pulse, _block_inputs(block_or_design, pulse)
    T = float(pls.duration)
    try:
        check_run_steps(block, T)
    except ValueError as exc:
        raise OptionError(str(exc), ("--duration",), tuple(notices)) from None
    sim = simulate(block, pls, restitution=restitution, history=0 if history else None)
    notices += _run_notices(sim, T)
    housner = float(block.housner_ratio)
    # Housner's ratio assumes the block rocks on about the other corner after an impact; for a
    # squat block it is <= 0 and the impact ends the rocking (the block lands flat): no ratio
    eta = restitution if restitution is not None else (housner if housner > 0.0 else None)
    given = {**inputs, "restitution": restitution, "design": design, "min_rotation": min_rotation}
    return SimulationRecord(
        block=block, pulse=pls, inputs={key: given[key] for key in _INPUTS},
        design=design, design_numbers=numbers, checks=checks, p=float(block.p), alpha=float(block.alpha),
        H=float(block.H), housner_ratio=housner, impact_ratio=eta, k_peak=float(pls.k_peak), duration=T,
        omega_p=float(pls.omega_p), min_rotation=min_rotation, simulation=sim, notices=tuple(notices))


def _run_notices(sim: Simulation, T: float) -> list[Notice]:
    """A run still moving at the time limit; steps with no admissible contact state."""
    out = []
    if not (sim.settled[0] or sim.overturned[0]):
        end = float(sim.end_time[0])
        out.append(Notice(STILL_MOVING, f"the block is still moving at t = {end:.6g} s, the time limit of "
                          f"the run (the pulse's {T:g} s + 60/p); its rotation and slide there are not "
                          "residual (JSON: settled false, residual_* null)", "end_time", end))
    if sim.unresolved:
        out.append(Notice(UNRESOLVED, f"{sim.unresolved} step(s) had no admissible contact state "
                          "(a stuck corner was assumed)", "unresolved", float(sim.unresolved)))
    return out


def _block_inputs(block: Block, pulse: Pulse) -> dict[str, Any]:
    """The inputs of a run given as objects, by the names of the options."""
    def num(v: object) -> float:
        return float(np.asarray(v, dtype=np.float64))

    return {"gamma": num(block.gamma), "half_width": num(block.B), "kprime": num(block.kprime),
            "mu": num(block.mu), "pulse": pulse.shape if pulse.t_samples is None else "file",
            "k_peak": num(pulse.k_peak), "duration": num(pulse.duration), "pulse_file": None,
            "buoyancy": num(block.buoyancy), "uplift": num(block.uplift),
            "uplift_ratio": num(block.uplift_ratio), "uplift_arm": num(block.uplift_arm),
            "gyration": None if block.i2 is None else math.sqrt(num(block.i2))}


def _options_run(opts: dict[str, Any]) -> tuple[Block, Pulse, dict[str, Any]]:
    """The block, the pulse and the inputs of the options of ``regimemap simulate``."""
    from .file import block_from_options, check_loads_and_gyration, pulse_from_options
    from .file_pulses import read_pulse_csv

    missing = [f"--{n.replace('_', '-')}" for n in ("gamma", "half_width", "mu") if opts[n] is None]
    if missing:
        raise OptionError(f"missing option(s) {', '.join(missing)}: give the block (--gamma, "
                          "--half-width, --mu, ...), or --design FILE.toml")
    pls = pulse_from_options(opts["pulse"], opts["k_peak"], opts["duration"], pulse_file=opts["pulse_file"],
                             read=read_pulse_csv, kprime=opts["kprime"])
    gyration = opts["gyration"]
    check_loads_and_gyration([opts["gamma"]], [opts["buoyancy"]], [opts["uplift"]],
                             [gyration] if gyration is not None else None)
    inputs = {key: opts[key] for key in _OPTION_DEFAULTS}
    if opts["pulse_file"] is not None:
        inputs["pulse"] = "file"
    return block_from_options(opts), pls, inputs


def _design_run(design: str, strict: bool, notices: list[Notice]
                ) -> tuple[Block, Pulse, dict[str, Any], dict[str, float], tuple[Check, ...]]:
    """The block, the pulse, the inputs, the numbers and the requirements of a design file's
    design wave; its implausible values appended to ``notices`` (refused under ``strict``)."""
    from ..caisson.file import DesignFileError, read_design
    from ..caisson.report import stability_checks
    from ..dynamics.design_wave import design_wave_inputs, design_wave_numbers, design_wave_run

    try:
        d = read_design(design)
    except DesignFileError as exc:
        raise OptionError(str(exc), ("--design",)) from None
    try:
        a = d.analyse()
    except ValueError as exc:
        _implausible(d, None, strict, design, notices)  # a unit slip may be why
        raise OptionError(f"{design}: {exc}", ("--design",), tuple(notices)) from None
    _implausible(d, a, strict, design, notices)
    h, T13 = d.site.depth, d.wave.period
    try:
        block, pulse = design_wave_run(a, h, T13)
    except ValueError as exc:
        raise OptionError(f"{design}: {exc}", ("--design",), tuple(notices)) from None
    checks = stability_checks(a, (d.caisson.required_sliding, d.caisson.required_overturning))
    inputs = {**design_wave_inputs(a, h, T13), "pulse_file": None}
    return block, pulse, inputs, design_wave_numbers(a, h, T13), tuple(checks)


def _implausible(d: Design, analysis: CaissonAnalysis | None, strict: bool, source: str,
                 notices: list[Notice]) -> None:
    """Append the implausible values of design ``d``
    (:func:`regimemap.caisson.file_plausibility.implausible_values`) to ``notices``; under
    ``strict``, refuse the first."""
    from ..caisson.file_plausibility import implausible_values

    found = implausible_values(d, analysis)
    if found and strict:
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        raise OptionError(f"{source}: {found[0]}{more}; --strict refuses implausible values", ("--design",))
    notices += [Notice(IMPLAUSIBLE, f"{source}: {item}", item.key, item.value) for item in found]
