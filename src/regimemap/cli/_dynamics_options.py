"""Options shared by ``regimemap simulate`` and ``regimemap outcome`` (and the figure formats of
``regimemap dynamics-figures``): the block and pulse options, their types, the output checks,
and :class:`~regimemap.motion.file.OptionError` as click's usage errors."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import Any

import click

from ..dynamics.limits import INPUT_LIMITS, MAX_AXIS_VALUES, check_input
from ..dynamics.pulses import SHAPES
from ..motion.file import OptionError
from ._common import Checked, ParamType, Values, gamma_option, kprime_option
from ._writing import echo_notices

__all__ = [
    "input_number",
    "values_type",
    "input_option",
    "block_options",
    "min_rotation_option",
    "option_errors",
]

def input_number(what: str) -> ParamType:
    """One number in the range of input ``what`` of :data:`regimemap.dynamics.limits.INPUT_LIMITS`."""
    lim = INPUT_LIMITS[what]

    def check(text: str) -> float:
        try:
            v = float(text.strip())
        except ValueError:
            raise ValueError(f"{what} must be {lim.text}, got {text!r} (not a number)") from None
        if not lim.contains(v):
            raise ValueError(f"{what} must be {lim.text}, got {text!r}")
        return v + 0.0

    return Checked("number", check)


def values_type(what: str) -> ParamType:
    """A list ``a,b,c`` or a range ``start:stop:count`` of input ``what``, each value checked."""

    def check(v: float, what: str = what) -> float:
        return check_input(what, v)

    return Values(what, check, MAX_AXIS_VALUES)


_HELP = {
    "half_width": "Half width B of the block (m), 0.001 to 1000.",
    "mu": "Friction coefficient (0 to 100), static = kinetic.",
    "k_peak": "Peak of the pulse, F/(m g) (0 to 100); positive pushes towards O.",
    "duration": "Whole duration of the pulse (s), 1e-4 to 100.",
    "omega_p": "Instead of --duration: the pulse's circular frequency (rad/s): pi/duration, "
               "2 pi/duration for one-sine and one-cosine.",
    "restitution": "Ratio theta'+/theta'- of a rocking impact, 0 to 1 (default: Housner's plastic "
                   "impact, 1 - 1.5 sin^2(alpha) for a uniform block).",
    "buoyancy": "Buoyancy, upward through C, in units of m g (0 to <1). Default 0.",
    "uplift": "Uplift on the base, in units of m g (0 to <1; buoyancy + uplift < 1). Default 0.",
    "uplift_ratio": "Uplift proportional to the push: U = uplift m g + ratio F (0 to 10). Default 0.",
    "uplift_arm": "Where the uplift acts, from C towards O' over B (-1 to 1). Default 1/3 "
                  "(a triangular uplift pressure).",
    "gyration": "Radius of gyration about C over B (default: the uniform block's, "
                "sqrt((1 + gamma^2)/3)); 0.001 to sqrt(1 + gamma^2).",
}

_SWEEPS = " A list a,b,c or a range start:stop:count sweeps it."


def input_option(name: str, swept: bool, metavar: str, default: Any = None, required: bool = False,
                 extra: str = "") -> Callable[[Any], Any]:
    """``--name`` of input ``name``: one number, or (``swept``) a list or range of them.

    A ``default`` of None is not passed to click: click 8.3 and later take an explicit None as a
    default given, and would not refuse a ``required`` option left out.
    """
    flag = "--" + name.replace("_", "-")
    typ = values_type(name) if swept else input_number(name)
    text = _HELP[name] + (extra if swept else "")
    given = {} if default is None else {"default": default}
    return click.option(flag, name, type=typ, required=required,
                        metavar=("LIST" if swept else metavar), help=text, **given)


def block_options(swept: bool) -> Callable[[Any], Any]:
    """The block's and the pulse's options: one value each (simulate) or lists (outcome)."""
    more = _SWEEPS
    opts = [
        # simulate: --gamma, --half-width and --mu are required unless --design gives them
        (gamma_option(required=False) if not swept else
         click.option("--gamma", "gamma", required=True, type=values_type("gamma"), metavar="LIST",
                      help="Aspect ratio gamma = H/B (0.001 to 1000), H the height of C above the "
                           "base." + more)),
        input_option("half_width", swept, "B", required=swept, extra=more),
        (kprime_option(required=False) if not swept else
         click.option("--kprime", "kprime", type=values_type("kprime"), metavar="LIST",
                      help="Height of the push above C over H, in [-1, 1]." + more)),
        input_option("mu", swept, "MU", required=swept, extra=more),
        click.option("--pulse", "pulse", type=click.Choice(SHAPES), default=None,
                     help="Shape of the force pulse (see docs/dynamics.md)."),
        input_option("k_peak", swept, "K", extra=more),
        input_option("duration", swept, "T", extra=more),
        input_option("restitution", False, "E"),
        input_option("buoyancy", swept, "BETA", default=0.0 if not swept else None, extra=more),
        input_option("uplift", swept, "U", default=0.0 if not swept else None, extra=more),
        input_option("uplift_ratio", swept, "NU", default=0.0 if not swept else None, extra=more),
        input_option("uplift_arm", swept, "E_U", default=1.0 / 3.0 if not swept else None, extra=more),
        input_option("gyration", swept, "R", extra=more),
    ]

    def deco(f: Any) -> Any:
        for o in reversed(opts):
            f = o(f)
        return f

    return deco


def min_rotation_option() -> Callable[[Any], Any]:
    """``--min-rotation ANGLE`` (degrees, default 0): rocking counts only above it (``simulate``
    and ``outcome`` share this one definition; the library takes radians)."""
    return click.option(
        "--min-rotation", "min_rotation", type=input_number("min_rotation"), default=0.0, show_default=True,
        metavar="ANGLE",
        help="Count rocking only if the largest |theta| exceeds ANGLE (degrees, 0 to 90): a run "
             "that rocked less is 'slide only' (if it slid) or 'rest'.  Default 0: every rocking "
             "phase counts, however small.")


@contextlib.contextmanager
def option_errors() -> Iterator[None]:
    """An :class:`~regimemap.motion.file.OptionError` inside becomes a usage error (exit 2):
    ``Invalid value for '--opt'`` when it names options, the message alone when not; the
    warnings it carries are printed first (:func:`echo_notices`)."""
    try:
        yield
    except OptionError as exc:
        echo_notices(exc.notices)
        if exc.options:
            hint = " / ".join(f"'{o}'" for o in exc.options)
            raise click.BadParameter(str(exc), param_hint=hint) from None
        raise click.UsageError(str(exc)) from None
