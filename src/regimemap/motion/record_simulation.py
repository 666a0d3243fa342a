"""One run of ``regimemap simulate`` as JSON, text and a time-history file.

* :func:`simulation_record` -- a :class:`~regimemap.motion.record.SimulationRecord` as a
  JSON-ready dict (numbers rounded to 12 significant digits), :func:`simulation_json` as one
  JSON object, :func:`format_simulation` as text for people (a design-wave run's numbers in
  words: :func:`describe_design_wave`);
* :func:`write_simulation_history` -- its time history, ``.csv`` or ``.npz``
  (:func:`write_history`, atomically).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..dynamics.stepper import History, Phase
from ..io.csv import write_csv
from ..io.formats import format_for, record_formats
from ..io.json import json_text
from ..io.npz import write_npz
from ..mechanics.modes import Mode
from ..records.numbers import optional_float, rounded

if TYPE_CHECKING:  # pragma: no cover
    from .record import SimulationRecord

__all__ = ["HISTORY_FORMATS", "describe_design_wave", "format_simulation", "history_arrays",
           "phase_description", "simulation_json", "simulation_record", "write_history",
           "write_simulation_history"]

_PHASE_BY_LABEL = {ph.label: ph for ph in Phase}


def phase_description(label: str) -> str:
    """What a phase label (RE, SL, RO, ..., FLIGHT) means, in words."""
    ph = _PHASE_BY_LABEL[label]
    return "free flight (no corner in contact)" if ph is Phase.FLIGHT else Mode(int(ph)).description


def simulation_record(record: SimulationRecord) -> dict[str, Any]:
    """A run (:class:`~regimemap.motion.record.SimulationRecord`) as a JSON-ready dict.

    Keys: ``overturned``, ``category`` (rocking counted above the record's ``min_rotation``),
    ``max_rotation`` (rad), ``max_rotation_deg``, ``residual_rotation`` (rad),
    ``residual_rotation_deg``, ``residual_slide`` (m, positive towards O), ``impacts``,
    ``initial_mode``, ``phases`` (list of {``mode``, ``start``} in s), ``settled``, ``end_time``
    (s), ``steps``, ``derived`` (p, alpha, ..., ``impact_ratio`` None when Housner's ratio does
    not apply, a squat block's) and ``inputs``; for a design file's run, ``design`` (where its
    numbers came from, with their units) and ``checks`` (its requirements).  Floats are rounded
    to 12 significant digits (:func:`regimemap.records.numbers.rounded`).  A run still moving at
    the time limit (``settled`` false, not overturned; category "still moving") has no residuals: the three
    ``residual_*`` are None.
    """
    sim = record.simulation
    phases = sim.phases[0] if sim.phases is not None else []
    init = int(sim.initial_mode[0])

    def residual(v: float) -> float | None:
        return float(v) if record.finished else None

    out = {
        "overturned": bool(sim.overturned[0]),
        "category": record.category,
        "max_rotation": float(sim.max_rotation[0]),
        "max_rotation_deg": math.degrees(float(sim.max_rotation[0])),
        "residual_rotation": residual(sim.residual_rotation[0]),
        "residual_rotation_deg": residual(math.degrees(float(sim.residual_rotation[0]))),
        "residual_slide": residual(sim.residual_slide[0]),
        "impacts": int(sim.impacts[0]),
        "initial_mode": Phase(init).label if init >= 0 else None,
        "phases": [{"mode": label, "start": float(t)} for label, t in phases],
        "settled": bool(sim.settled[0]),
        "end_time": float(sim.end_time[0]),
        "steps": int(sim.steps[0]),
        "derived": {key: optional_float(v) for key, v in record.derived.items()},
        "inputs": dict(record.inputs),
    }
    if record.design_numbers is not None:
        from ..dynamics.design_wave import DESIGN_UNITS, NO_ADDED_MASS, PROFILE
        from ..records.checks import checks_json

        numbers = {key: float(v) for key, v in record.design_numbers.items()}
        out["design"] = {"file": record.design, **numbers,
                         "profile": PROFILE, "added_mass_note": NO_ADDED_MASS, "units": dict(DESIGN_UNITS)}
        out["checks"] = checks_json(record.checks)
    return rounded(out)


def simulation_json(record: SimulationRecord, files: Sequence[str] = ()) -> str:
    """A run as one JSON object (:func:`simulation_record`) with the ``files`` written, indented."""
    return json_text({**simulation_record(record), "files": list(files)})


def _num(x: float, digits: int = 6) -> str:
    v = float(x)
    return f"{v:.{digits}g}" if v != 0.0 else "0"


#: Phases listed in full up to this many; beyond, the first and the last ones.
_PHASES_SHOWN = 24


def format_simulation(record: SimulationRecord | Mapping[str, Any]) -> str:
    """A run as text for people: a design file's line (where its numbers came from), the block and
    pulse, the phases of the motion with their start times, the outcome, and the design file's
    requirements, PASS or FAIL.

    ``record`` is a :class:`~regimemap.motion.record.SimulationRecord`, or its JSON dict
    (:func:`simulation_record`), which gives the lines of the run alone.
    """
    if isinstance(record, Mapping):
        return _format_run(record)
    lines = []
    if record.design_numbers is not None:

        lines.append("design     " + describe_design_wave(record.design_numbers, record.design))
    lines.append(_format_run(simulation_record(record)))
    if record.checks:
        from ..records.checks import checks_lines

        lines.append("design check of the file (--check: exit status 1 when a requirement fails)")
        lines += checks_lines(record.checks)
    return "\n".join(lines)


def _format_run(record: Mapping[str, Any]) -> str:
    """The lines of a run (its JSON dict): the block and pulse, the phases, the outcome."""
    inp = record["inputs"]
    der = record["derived"]
    lines = []
    H = inp["gamma"] * inp["half_width"]
    kp = "from the pulse file" if inp.get("kprime") is None else _num(inp["kprime"])
    lines.append(f"block      B = {_num(inp['half_width'])} m, H = {_num(H)} m "
                 f"(gamma = {_num(inp['gamma'])}), mu = {_num(inp['mu'])}, k' = {kp}")
    if der.get("impact_ratio") is None:  # a squat block: Housner's ratio would be <= 0
        impact = (f"impact ratio not applicable (a squat block: Housner's (I + m(H^2 - B^2))/(I + "
                  f"m(H^2 + B^2)) = {_num(der['housner_ratio'], 4)} <= 0, its rocking ends at the "
                  "first impact: the block lands flat)")
    else:
        impact = (f"impact ratio {_num(der['impact_ratio'], 4)}"
                  + (" (Housner)" if inp.get("restitution") is None else " (--restitution)"))
    lines.append(f"           p = {_num(der['p'], 5)} rad/s, alpha = {_num(der['alpha'], 5)} rad "
                 f"({_num(math.degrees(der['alpha']), 4)} deg), {impact}")
    loads = [f"{name} = {_num(inp[key])}" for key, name in
             (("buoyancy", "buoyancy"), ("uplift", "uplift"), ("uplift_ratio", "uplift ratio"))
             if inp.get(key)]
    if loads:
        lines.append(f"loads      {', '.join(loads)}, uplift arm = {_num(inp['uplift_arm'])} B")
    if inp.get("pulse_file"):
        lines.append(f"pulse      from {inp['pulse_file']}: peak |k| = {_num(der['k_peak'])}, "
                     f"duration {_num(der['duration'])} s")
    else:
        lines.append(f"pulse      {inp['pulse']}, k_peak = {_num(inp['k_peak'])}, duration = "
                     f"{_num(inp['duration'])} s (omega_p = {_num(der['omega_p'], 5)} rad/s, "
                     f"omega_p/p = {_num(der['omega_p'] / der['p'], 4)})")
    phases = record["phases"]
    lines.append(f"phases     {len(phases)} (start time in s, mode)")
    shown: list[Any] = list(phases)
    if len(phases) > _PHASES_SHOWN:
        shown = phases[:18] + [None] + phases[-4:]
    for ph in shown:
        if ph is None:
            lines.append(f"  ... {len(phases) - 22} more ...")
            continue
        lines.append(f"  {_num(ph['start']):>10s}  {ph['mode']:6s}  {phase_description(ph['mode'])}")
    over = "OVERTURNED" if record["overturned"] else "not overturned"
    if record["overturned"]:
        end = f"overturning declared at t = {_num(record['end_time'])} s"
    elif record["settled"]:
        end = f"came to rest at t = {_num(record['end_time'])} s"
    else:
        end = f"still moving at t = {_num(record['end_time'])} s, the time limit"
    lines.append(f"outcome    {record['category']}: {over} ({end})")
    if inp.get("min_rotation"):
        lines.append(f"  rocking counts above a max rotation of {_num(inp['min_rotation'])} deg "
                     "(--min-rotation)")
    lines.append(f"  max rotation        {_num(record['max_rotation'])} rad "
                 f"({_num(record['max_rotation_deg'], 4)} deg)")
    if record["residual_slide"] is None:  # still moving: nothing is residual yet
        lines.append("  residual rotation   none: still moving at the time limit")
        lines.append("  residual slide      none: still moving at the time limit")
    else:
        lines.append(f"  residual rotation   {_num(record['residual_rotation'])} rad "
                     f"({_num(record['residual_rotation_deg'], 4)} deg)")
        lines.append(f"  residual slide      {_num(record['residual_slide'])} m (positive towards O)")
    lines.append(f"  impacts             {record['impacts']}")
    init = record["initial_mode"]
    lines.append(f"  initial mode        {init} ({phase_description(init)})" if init else
                 "  initial mode        none")
    return "\n".join(lines)




def write_simulation_history(path: str | os.PathLike[str], record: SimulationRecord) -> str:
    """Write the time history of a run kept with ``history=True`` (:func:`write_history`, its
    number and text inputs alongside in ``.npz``), atomically; the format."""
    if record.simulation.history is None:
        raise ValueError("the run kept no time history: run_simulation(..., history=True)")
    scalars = {k: v for k, v in record.inputs.items() if isinstance(v, (int, float, str))}
    return write_history(path, record.simulation.history, record.H, scalars)


#: Formats of a time history, by file suffix (:data:`~regimemap.io.formats.RECORDS`).
HISTORY_FORMATS: tuple[str, ...] = record_formats("time history")


def history_arrays(history: History, H: float) -> dict[str, NDArray[Any]]:
    """The columns of a time history: t, k, x, y, theta, vx, vy, omega, slide (of the base,
    positive towards O) and phase (the label of the step ending at t; '' at t = 0)."""
    labels = np.array([""] + [ph.label for ph in Phase])
    return {
        "t": history.t, "k": history.k, "x": history.x, "y": history.y, "theta": history.theta,
        "vx": history.vx, "vy": history.vy, "omega": history.omega, "slide": history.base_slide(H),
        "phase": labels[history.phase.astype(np.int64) + 1],
    }


def write_history(path: str | os.PathLike[str], history: History, H: float,
                  inputs: Mapping[str, Any] | None = None) -> str:
    """Write the time history of a run, atomically; the format (csv or npz) from the suffix.

    ``.csv``: a header and one row per step (numbers as ``repr``, so they read back exactly).
    ``.npz``: the same columns as 1-D arrays, and the inputs as 0-d arrays.
    Returns the format.
    """
    fmt = format_for(path, "time history")
    cols = history_arrays(history, H)
    if fmt == "npz":
        write_npz(path, cols, inputs)
        return fmt
    names = list(cols)
    numeric = [cols[n].tolist() for n in names[:-1]]
    phase = cols["phase"].tolist()
    write_csv(path, names, (",".join(repr(float(c[i]) + 0.0) for c in numeric) + f",{phase[i]}"
                            for i in range(len(phase))))
    return fmt


def describe_design_wave(numbers: Mapping[str, float], source: str | None = None) -> str:
    """One line saying where a design-wave run's numbers come from
    (:func:`~regimemap.dynamics.design_wave.design_wave_numbers`).

    Examples
    --------
    >>> from regimemap.caisson.file import example_design_text, parse_design
    >>> from regimemap.dynamics.design_wave import design_wave_numbers
    >>> d = parse_design(example_design_text())
    >>> print(describe_design_wave(design_wave_numbers(d.analyse(), d.site.depth, d.wave.period),
    ...                            "goda.toml"))  # doctest: +NORMALIZE_WHITESPACE
    goda.toml: design wave Hmax = 8.050 m (h = 10.1 m, T1/3 = 11.4 s): k = P/(m g) = 0.277621,
    tau0 = (0.5 - Hmax/(8 h)) T1/3 = 4.5643 s, uplift U = 0.524144 P in phase; rigid block, no added mass
    """
    n = numbers
    where = f"{source}: " if source else ""
    return (f"{where}design wave Hmax = {n['Hmax']:.3f} m (h = {n['depth']:g} m, T1/3 = {n['period']:g} s): "
            f"k = P/(m g) = {n['k']:.6g}, tau0 = (0.5 - Hmax/(8 h)) T1/3 = {n['tau0']:.5g} s, "
            f"uplift U = {n['uplift_ratio']:.6g} P in phase; rigid block, no added mass")
