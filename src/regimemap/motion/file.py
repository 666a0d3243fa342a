"""A run and an outcome map from flat options (the command line's), checked, without click.

``regimemap simulate`` and ``regimemap outcome`` hand their options here, named as in
:data:`regimemap.dynamics.limits.INPUT_LIMITS` (the option without ``--``, ``_`` for ``-``);
each value has been range-checked already.  What is checked here is how the options go
together: a pulse is a shape with its peak and duration or a sampled history, an outcome map
sweeps exactly two inputs, the loads leave the block some weight, the runs stay within the
work limits.  A problem is an :class:`OptionError` that names the options concerned.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..dynamics.block import Block
from ..dynamics.limits import MAX_MAP_RUNS, check_gyration, check_map_steps, check_net_weight
from ..dynamics.pulses import SHAPES, Pulse
from ..records.notices import Notice

__all__ = [
    "OptionError",
    "BLOCK_FIELDS",
    "MAP_INPUTS",
    "block_from_options",
    "pulse_from_options",
    "check_loads_and_gyration",
    "MapOptions",
    "map_options",
]

FloatArray = NDArray[np.float64]

#: Option name -> the field of :class:`~regimemap.dynamics.Block` it sets.
BLOCK_FIELDS: dict[str, str] = {
    "half_width": "B", "gamma": "gamma", "mu": "mu", "kprime": "kprime", "gyration": "i2",
    "buoyancy": "buoyancy", "uplift": "uplift", "uplift_ratio": "uplift_ratio", "uplift_arm": "uplift_arm"}
#: The inputs an outcome map can sweep, in the order of the options of ``regimemap outcome``.
MAP_INPUTS: tuple[str, ...] = ("k_peak", "duration", "omega_p", "mu", "kprime", "gamma", "half_width",
                               "gyration", "buoyancy", "uplift", "uplift_ratio", "uplift_arm")
#: The loads' values when not given.
_LOAD_DEFAULTS = {"buoyancy": 0.0, "uplift": 0.0, "uplift_ratio": 0.0, "uplift_arm": 1.0 / 3.0}


class OptionError(ValueError):
    """Options that do not go together.

    Parameters
    ----------
    message : str
        What is wrong, and what to give instead.
    options : tuple of str
        The options concerned (``--name``); empty when it is the command line as a whole
        (a missing option, two that exclude each other).
    notices : tuple of Notice
        Warnings found before the error (a design file's implausible values), which may
        explain it.
    """

    def __init__(self, message: str, options: tuple[str, ...] = (), notices: tuple[Notice, ...] = ()) -> None:
        super().__init__(message)
        self.options = options
        self.notices = notices


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _cycles(shape: str) -> float:
    """Half periods of a pulse shape: omega_p = cycles pi / duration."""
    return 2.0 if shape in ("one-sine", "one-cosine") else 1.0


def block_from_options(values: Mapping[str, Any]) -> Block:
    """The :class:`~regimemap.dynamics.Block` of the options in :data:`BLOCK_FIELDS` (all given).

    ``kprime`` None is 0 (a pulse that carries its own k'); ``gyration`` None is the uniform
    block, else i2 = gyration^2.
    """
    fields = {BLOCK_FIELDS[n]: values[n] for n in BLOCK_FIELDS}
    fields["kprime"] = values["kprime"] if values["kprime"] is not None else 0.0
    fields["i2"] = None if values["gyration"] is None else values["gyration"] * values["gyration"]
    return Block(**fields)


def pulse_from_options(shape: str | None, k_peak: float | None, duration: float | None, *,
                       pulse_file: str | None = None, read: Callable[[str], Pulse] | None = None,
                       kprime: float | None = None) -> Pulse:
    """The pulse of one run: ``shape`` with ``k_peak`` and ``duration``, or a sampled history.

    Parameters
    ----------
    shape, k_peak, duration : str, float or None
        ``--pulse``, ``--k-peak`` and ``--duration``: all three, or none with ``pulse_file``.
    pulse_file : str, optional
        ``--pulse-file``: a sampled history, read with ``read`` (whose ValueError names the
        problem in the file).
    read : callable, optional
        Reads ``pulse_file`` (the command line's CSV reader).
    kprime : float, optional
        ``--kprime``: required unless the history carries its own k', excluded if it does.

    Returns
    -------
    Pulse

    Raises
    ------
    OptionError
        A missing or excluded option, or a bad file (naming ``--pulse-file``).
    """
    given = [n for n, v in (("--pulse", shape), ("--k-peak", k_peak), ("--duration", duration))
             if v is not None]
    if pulse_file is not None:
        if given:
            raise OptionError(f"{', '.join(given)} and --pulse-file exclude each other: give a pulse "
                              "shape or a file")
        if read is None:
            raise TypeError("pulse_file needs a reader (read=)")
        try:
            pulse = read(pulse_file)
        except ValueError as exc:
            raise OptionError(str(exc), ("--pulse-file",)) from None
        if pulse.has_kprime and kprime is not None:
            raise OptionError(f"--kprime and the kprime column of {pulse_file} exclude each other")
    else:
        missing = [n for n in ("--pulse", "--k-peak", "--duration") if n not in given]
        if missing:
            raise OptionError(f"missing option(s) {', '.join(missing)}: give --pulse KIND "
                              "--k-peak K --duration T, or --pulse-file FILE.csv")
        assert shape is not None and k_peak is not None and duration is not None
        pulse = Pulse.make(shape, k_peak, duration)
    if kprime is None and not pulse.has_kprime:
        raise OptionError("missing option --kprime: the height of the push above C over H, in "
                          "[-1, 1] (or a kprime column in --pulse-file)")
    return pulse


def check_loads_and_gyration(gammas: Sequence[float], buoyancy: Sequence[float],
                             uplift: Sequence[float], gyration: Sequence[float] | None) -> None:
    """Every block keeps some weight (buoyancy + uplift < 1) and has a possible radius of gyration.

    The extremes are checked: the largest loads, the largest gyration with the smallest gamma.

    Raises
    ------
    OptionError
        Naming ``--uplift`` and ``--buoyancy``, or ``--gyration``.
    """
    try:
        check_net_weight(max(buoyancy), max(uplift))
    except ValueError as exc:
        raise OptionError(str(exc), ("--uplift", "--buoyancy")) from None
    if gyration:
        try:
            check_gyration(max(gyration), min(gammas))
        except ValueError as exc:
            raise OptionError(str(exc), ("--gyration",)) from None


@dataclass(frozen=True)
class MapOptions:
    """The inputs of an outcome map, checked (see :func:`map_options`).

    Attributes
    ----------
    shape : str
        The pulse shape.
    swept : tuple of str
        The two swept inputs: along the columns, then the rows.
    values : dict
        Every input of :data:`MAP_INPUTS`: its values as given (the swept ones sorted), or None.
    fixed : dict
        The inputs not swept: their one value (the loads' defaults filled in), or None.
    """

    shape: str
    swept: tuple[str, str]
    values: dict[str, list[float] | None]
    fixed: dict[str, float | None]

    @property
    def n_runs(self) -> int:
        """The number of cells (runs) of the map."""
        return len(self.values[self.swept[0]] or []) * len(self.values[self.swept[1]] or [])

    def axis(self, i: int) -> FloatArray:
        """The values of swept input ``i`` (0: columns, 1: rows)."""
        return np.asarray(self.values[self.swept[i]] or [], dtype=np.float64)

    def sweep(self, i: int) -> tuple[str, FloatArray]:
        """Swept input ``i`` as :func:`~regimemap.dynamics.outcome_map` takes it: the name of
        the block field or pulse parameter, and its values (gyration as i2 = gyration^2)."""
        name, values = self.swept[i], self.axis(i)
        if name == "gyration":
            return "i2", values ** 2
        return BLOCK_FIELDS.get(name, name), values

    def block(self) -> Block:
        """The block of the map; a swept field holds its first value (the map replaces it)."""
        given = {n: self.axis(self.swept.index(n))[0] if n in self.swept else self.fixed[n]
                 for n in BLOCK_FIELDS}
        return block_from_options(given)

    def fixed_duration(self) -> float | None:
        """The pulse's duration when neither it nor omega_p is swept (s)."""
        w = self.fixed.get("omega_p")
        if w is not None:  # one frequency: its duration
            return _cycles(self.shape) * math.pi / w
        return self.fixed.get("duration")

    def longest_duration(self) -> float:
        """The longest pulse of the map (s)."""
        if self.values["duration"] is not None:
            return max(self.values["duration"] or [])
        return _cycles(self.shape) * math.pi / min(self.values["omega_p"] or [])

    def check_steps(self) -> int:
        """The time steps of the longest run: the longest pulse on the block of smallest p.

        Raises
        ------
        OptionError
            Over :data:`~regimemap.dynamics.limits.MAX_STEPS`, naming ``--duration`` or
            ``--omega-p``.
        """
        gs = np.asarray(self.values["gamma"] or [], dtype=np.float64)
        bs = np.asarray(self.values["half_width"] or [], dtype=np.float64)
        rg = self.values["gyration"]
        G3, B3, R3 = np.meshgrid(gs, bs, np.asarray(rg if rg else [math.nan]), indexing="ij")
        i2 = None if not rg else (R3 * R3).ravel()
        probe = Block(B=B3.ravel(), gamma=G3.ravel(), mu=0.0, i2=i2)
        try:
            return check_map_steps(probe, self.longest_duration())
        except ValueError as exc:
            option = "--duration" if self.values["duration"] is not None else "--omega-p"
            raise OptionError(str(exc), (option,)) from None


def _swept_inputs(values: dict[str, list[float] | None], order: Sequence[str]) -> tuple[str, str]:
    """The two swept inputs in command-line order, their values sorted (in ``values``)."""
    swept = [n for n in dict.fromkeys(order)
             if n in values and values[n] is not None and len(values[n] or []) > 1]
    if len(swept) != 2:
        got = ", ".join(_flag(n) for n in swept) or "none"
        raise OptionError("give exactly two swept inputs (lists a,b,c or ranges start:stop:count "
                          "with two or more values, e.g. --k-peak 0.3:1.5:121 --duration 0.2,0.5,1.2) "
                          f"and one value for every other input; swept: {got}")
    for name in swept:
        vals = sorted(values[name] or [])
        if any(b <= a for a, b in zip(vals, vals[1:])):
            raise OptionError("a value appears twice", (_flag(name),))
        values[name] = vals
    return swept[0], swept[1]


def _check_pulse(shape: str | None, values: Mapping[str, list[float] | None]) -> str:
    if shape is None:
        raise OptionError(f"missing option --pulse: the shape of the force pulse ({', '.join(SHAPES)})")
    if values["k_peak"] is None:
        raise OptionError("missing option --k-peak: the peak of the pulse (0 to 100), one value or a list")
    if (values["duration"] is None) == (values["omega_p"] is None):
        raise OptionError("give one of --duration (s) or --omega-p (rad/s)" if values["duration"] is None
                          else "--duration and --omega-p exclude each other")
    if values["kprime"] is None:
        raise OptionError("missing option --kprime: the height of the push above C over H, in [-1, 1]")
    return shape


def map_options(values: Mapping[str, Sequence[float] | None], order: Sequence[str], shape: str | None,
                *, dimensionless: bool = False) -> MapOptions:
    """The inputs of an outcome map from its options, checked in the order the command reports.

    Parameters
    ----------
    values : mapping
        Every input of :data:`MAP_INPUTS`: its list of values (one value: not swept), or None.
    order : sequence of str
        The inputs in the order given on the command line: the first swept one runs along the
        columns, the second along the rows.
    shape : str or None
        ``--pulse``.
    dimensionless : bool
        ``--dimensionless``: the axes in omega_p/p and k_peak/tan(alpha), for one block.

    Returns
    -------
    MapOptions

    Raises
    ------
    OptionError
        A missing block input, not exactly two swept inputs, a value twice, a missing or
        excluded pulse option, loads leaving no weight, dimensionless axes that do not apply, more than
        :data:`~regimemap.dynamics.limits.MAX_MAP_RUNS` runs.
    """
    vals: dict[str, list[float] | None] = {n: (None if values.get(n) is None else list(values[n] or []))
                                           for n in MAP_INPUTS}
    missing = [_flag(n) for n in ("gamma", "half_width", "mu") if vals[n] is None]
    if missing:
        raise OptionError(f"missing option(s) {', '.join(missing)}: give the block (--gamma, --half-width) "
                          "and its friction (--mu), one value or a list each")
    swept = _swept_inputs(vals, order)
    shape = _check_pulse(shape, vals)
    fixed = {n: (v[0] if v else None) for n, v in vals.items() if n not in swept}
    for n, d in _LOAD_DEFAULTS.items():
        if n not in swept and fixed[n] is None:
            fixed[n] = d
    check_loads_and_gyration(vals["gamma"] or [], vals["buoyancy"] or [0.0], vals["uplift"] or [0.0],
                             vals["gyration"])
    if dimensionless:
        from ..dynamics.outcome import DIMENSIONLESS

        varying = [n for n in swept if n in ("gamma", "half_width", "gyration")]
        if varying:
            raise OptionError(f"the dimensionless axes need one block, but {_flag(varying[0])} is swept "
                              "(p and alpha would change from cell to cell)", ("--dimensionless",))
        if not any(n in DIMENSIONLESS for n in swept):
            raise OptionError("the dimensionless axes are omega_p/p and k_peak/tan(alpha): sweep "
                              "--k-peak, --duration or --omega-p", ("--dimensionless",))
    opts = MapOptions(shape, swept, vals, fixed)
    if opts.n_runs > MAX_MAP_RUNS:
        raise OptionError(f"{opts.n_runs} runs exceed the limit of {MAX_MAP_RUNS}; give fewer values")
    return opts
