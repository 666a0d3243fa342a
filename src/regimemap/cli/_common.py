"""The options shared by the commands: their types, checks and the loads of a block.

Every command takes gamma, k' and the loads (buoyancy, uplift, inertia) from here, so that
they read and fail alike.  What a command writes and prints is :mod:`._writing`'s; how the
process starts and ends (every error one line, Ctrl-C) :mod:`._main`'s."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, TypeVar, overload

import click

from ..mechanics.validation import (
    GAMMA_MAX,
    GAMMA_MIN,
    LOAD_LIMITS,
    MAX_AXIS,
    MIN_AXIS,
    check_axis_end,
    check_gamma,
    check_kprime,
    check_loads,
    check_resolution,
    check_weight,
)

if TYPE_CHECKING:  # pragma: no cover
    from click.decorators import FC

    from ..dynamics.limits import Limit


    #: Base of the option types.  Recent click makes ParamType generic in the
    #: converted value; click 8.1 cannot subscript it at run time.
    ParamType = click.ParamType[Any]
else:
    ParamType = click.ParamType

__all__ = [
    "CONTEXT_SETTINGS",
    "Checked",
    "LOAD_OPTIONS",
    "ParamType",
    "Values",
    "check_kprime_crest",
    "check_load_value",
    "gamma_option",
    "given_options",
    "kprime_option",
    "load_options",
    "load_range",
    "axis_end",
    "number_in",
    "resolution_type",
]

CONTEXT_SETTINGS = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


class Checked(ParamType):
    """A value as typed, checked and converted by ``check``, whose ValueError is the usage error's
    message (exit 2, after ``Invalid value for '--option':``); a value that is not text (a
    default, or a value already converted) is kept.  ``name``: the kind the help shows."""

    def __init__(self, name: str, check: Callable[[str], Any]):
        self.name = name
        self._check = check

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return value
        try:
            return self._check(value)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


def _number(name: str, check: Callable[[float], Any], allowed: str, kind: str | None = None) -> Checked:
    """A number as typed, checked by one of :mod:`regimemap.mechanics.validation`'s checks; the
    message names the parameter, what it allows and the value as typed (click prefixes the
    option's name).  ``kind``: the type's name (default ``name``)."""
    def convert(text: str) -> Any:
        try:
            number = float(text)
        except ValueError:
            raise ValueError(f"{name} must be {allowed}, got {text!r} (not a number)") from None
        try:
            return check(number)
        except ValueError:
            raise ValueError(f"{name} must be {allowed}, got {text!r}") from None

    return Checked(kind or name, convert)


GAMMA = _number("gamma", check_gamma, f"a finite number in [{GAMMA_MIN:g}, {GAMMA_MAX:g}]")


def axis_end(name: str) -> ParamType:
    """A click type for the end of a map's axis, a finite float in [MIN_AXIS, MAX_AXIS]."""
    allowed = f"a finite number in [{MIN_AXIS:g}, {MAX_AXIS:g}]"
    return _number(name, lambda v: check_axis_end(name, v), allowed)


#: ``--resolution``: samples along an axis, a whole number in [2, 5000].
resolution_type = Checked("integer", functools.partial(check_resolution, "resolution"))


def gamma_option(**kwargs: Any) -> Callable[[FC], FC]:
    """``--gamma`` (aspect ratio H/B > 0)."""
    kwargs.setdefault("required", True)
    return click.option("--gamma", type=GAMMA,
                        help=f"Aspect ratio gamma = H/B ({GAMMA_MIN:g} to {GAMMA_MAX:g}).",
                        **kwargs)


def kprime_option(**kwargs: Any) -> Callable[[FC], FC]:
    """``--kprime`` (force height h/H in [-1, 1], or [-1, crest] with ``--crest``).

    Use it with :func:`load_options`, which checks the range once the crest is known.
    """
    kwargs.setdefault("required", True)
    return click.option("--kprime", type=_KprimeUpToCrest(),
                        help="Force height k' = h/H in [-1, 1] (negative below the centre of mass).",
                        **kwargs)


# -- the loads of a block (buoyancy, uplift, inertia) --------------------------------------

#: The load options of the commands: (keyword of Parameters, option, metavar, help).
LOAD_OPTIONS: tuple[tuple[str, str, str, str], ...] = (
    ("buoyancy", "--buoyancy", "BETA",
     "Buoyancy over the dry weight, beta in [0, 1), upward through C (default 0)."),
    ("uplift", "--uplift", "U",
     "Uplift at zero push over the dry weight, u >= 0 (default 0)."),
    ("uplift_ratio", "--uplift-ratio", "NU",
     "Growth of the uplift with the push, nu >= 0: U = (u + nu k) m g (default 0)."),
    ("uplift_arm", "--uplift-arm", "E_U",
     "Where the uplift acts, from C towards the seaward corner O', over B, in [-1, 1] "
     "(default 1/3: Goda's triangle)."),
    ("gyration", "--gyration", "I",
     "Radius of gyration about C over B, i >= 0.001 (default: the uniform block, "
     "i^2 = (1 + gamma^2)/3)."),
    ("crest", "--crest", "CREST",
     "Top of the block above C over H, > 0 (default 1); the force may act up to it: "
     "kprime in [-1, CREST]."),
)


def load_range(name: str) -> str:
    """The allowed range of a load, as the messages write it: ``a number in [0, 1)``."""
    lo, hi, lo_open, hi_open = LOAD_LIMITS[name]
    return f"a number in {'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}"


def check_load_value(name: str, value: Any) -> float:
    """One load checked as :class:`~regimemap.mechanics.block.Parameters` checks it."""
    index = [n for n, *_ in LOAD_OPTIONS].index(name)
    out = check_loads(**{name: value})[index]
    assert out is not None
    return out


class _KprimeText(float):
    """A k' as typed (``text``), checked against the crest once the crest is known."""

    text: str


class _KprimeUpToCrest(ParamType):
    """``--kprime`` of a command with loads: a number; its range [-1, crest] is checked later."""

    name = "kprime"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, float):
            return value
        try:
            v = _KprimeText(float(value))
        except ValueError:
            self.fail(f"kprime must be a number in [-1, 1] (up to --crest), got {value!r} "
                      "(not a number)", param, ctx)
        v.text = str(value)
        top = LOAD_LIMITS["crest"][1]
        if not -1.0 <= v <= top:  # beyond any crest (and NaN): refused at once
            self.fail(f"kprime must be a number in [-1, 1] (up to --crest), got {value!r}",
                      param, ctx)
        return v


def check_kprime_crest(kprime: float, crest: float, option: str = "--kprime") -> float:
    """``kprime`` checked against [-1, crest]; a usage error naming the option if outside."""
    try:
        return check_kprime(float(kprime), crest)
    except ValueError:
        got = kprime.text if isinstance(kprime, _KprimeText) else kprime
        raise click.BadParameter(f"kprime must be a number in [-1, {crest:g}], got {got!r}",
                                 param_hint=f"'{option}'") from None


def _load_type(name: str) -> ParamType:
    return _number(name, lambda v: check_load_value(name, v), load_range(name))


def number_in(name: str, limit: Limit) -> ParamType:
    """A click type for a finite float in the range of ``limit``
    (:class:`regimemap.dynamics.limits.Limit`): NaN, an infinity, a value outside or a word is
    refused with the range, e.g. ``gap must be a finite number in (0, 8760], got 'nan'``."""
    def check(v: float) -> float:
        if not limit.contains(v):
            raise ValueError(name)
        return v

    return _number(name, check, limit.text, kind="number")


class Values(ParamType):
    """A list ``a,b,c`` or a range ``start:stop:count`` of at most ``max_count`` numbers, each
    checked by ``check`` (atlas, animate, outcome: :func:`regimemap.maps.sweeps.parse_values`)."""

    def __init__(self, name: str, check: Callable[[float], float], max_count: int):
        self.name = f"{name}-list"
        self._what = name
        self._check = check
        self._max = max_count

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> list[float]:
        if isinstance(value, list):
            return value
        from ..maps.sweeps import parse_values

        try:
            return parse_values(str(value), self._what, self._check, self._max)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


_F = TypeVar("_F", bound=Callable[..., Any])


@overload
def load_options(f: _F) -> _F: ...


@overload
def load_options(f: None = None, *, sweep: int | None = None) -> Callable[[_F], _F]: ...


def load_options(f: Callable[..., Any] | None = None, *, sweep: int | None = None) -> Any:
    """Add ``--buoyancy``, ``--uplift``, ``--uplift-ratio``, ``--uplift-arm``, ``--gyration``
    and ``--crest`` to a command; it receives them as one keyword, ``loads``.

    ``loads`` holds the keywords of :class:`~regimemap.mechanics.block.Parameters`
    that were given (``{}`` for the report's block), each checked (a usage error,
    exit 2, names the option and its range).  A ``--kprime`` of the command is
    checked against [-1, crest] here, since the crest may come after it.
    Place it under ``@click.command`` like any option.

    ``@load_options(sweep=N)`` (atlas, animate): each option takes a list
    ``a,b,c`` or a range ``start:stop:count`` of at most N values, and
    ``loads`` maps each given load to its list of values.
    """
    if f is None:
        return functools.partial(load_options, sweep=sweep)

    @functools.wraps(f)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        loads = {name: kwargs.pop(name) for name, *_ in LOAD_OPTIONS}
        loads = {name: v for name, v in loads.items() if v is not None}
        if sweep is None and kwargs.get("kprime") is not None:
            kwargs["kprime"] = check_kprime_crest(kwargs["kprime"], loads.get("crest", 1.0))
        if sweep is None:
            try:
                check_weight(loads.get("buoyancy", 0.0), loads.get("uplift", 0.0),
                             loads.get("uplift_ratio", 0.0))
            except ValueError as exc:
                raise click.BadParameter(str(exc), param_hint="'--uplift'") from None
        return f(*args, loads=loads, **kwargs)

    out: Callable[..., Any] = wrapper
    for name, option, metavar, text in reversed(LOAD_OPTIONS):
        check = functools.partial(check_load_value, name)
        kind = _load_type(name) if sweep is None else Values(name, check, sweep)
        if sweep is not None:
            metavar, text = "LIST", text + " A list a,b,c or a range start:stop:count sweeps it."
        out = click.option(option, name, type=kind, default=None, metavar=metavar,
                           help=text)(out)
    return out


# -- the options several commands take, each declared once -------------------------------------

#: ``--json`` of the commands that print one report.
JSON_HELP = "Print one JSON object instead of text."
#: ``--quiet`` of the commands with a progress bar and notes.
QUIET_HELP = "No progress bar and no notes on standard error."


def option_group(*options: Callable[[FC], FC]) -> Callable[[FC], FC]:
    """The options as one decorator, listed in ``--help`` in the order given."""
    def decorate(f: FC) -> FC:
        for option in reversed(options):
            f = option(f)
        return f

    return decorate


def json_option(help: str = JSON_HELP) -> Callable[[FC], FC]:
    """``--json``, passed to the command as ``as_json``."""
    return click.option("--json", "as_json", is_flag=True, help=help)


def quiet_option(help: str = QUIET_HELP) -> Callable[[FC], FC]:
    """``--quiet`` / ``-q``: no progress bar (and, as ``help`` says, no notes)."""
    return click.option("--quiet", "-q", is_flag=True, help=help)


def jobs_option(help: str) -> Callable[[FC], FC]:
    """``--jobs`` / ``-j N``: worker processes, 1 to 256 (default None: one per core)."""
    return click.option("--jobs", "-j", type=click.IntRange(1, 256), default=None, metavar="N", help=help)


def outputs_option(help: str, **kwargs: Any) -> Callable[[FC], FC]:
    """``-o`` / ``--output FILE``, repeatable, passed to the command as ``outputs``."""
    return click.option("-o", "--output", "outputs", type=click.Path(dir_okay=False), metavar="FILE",
                        multiple=True, help=help, **kwargs)


def output_option(help: str, metavar: str = "FILE", **kwargs: Any) -> Callable[[FC], FC]:
    """``-o`` / ``--output FILE``: one file (not a folder), passed to the command as ``output``."""
    return click.option("-o", "--output", "output", type=click.Path(dir_okay=False), metavar=metavar,
                        help=help, **kwargs)


def view_option(help: str) -> Callable[[FC], FC]:
    """``--view designer|report`` (default designer): the map's automatic view."""
    return click.option("--view", type=click.Choice(["designer", "report"]), default="designer",
                        show_default=True, help=help)


def axis_options(k_help: str, mu_help: str, *, metavars: bool = True) -> Callable[[FC], FC]:
    """``--k-max K`` and ``--mu-max MU``: the ends of the map's axes (default None: automatic).

    Without ``metavars`` (``plot``) the values are shown and named as the options are
    (``K-MAX``, ``k-max must be ...``).
    """
    return option_group(*(
        click.option(f"--{axis}-max", type=axis_end(f"{axis}{'_' if metavars else '-'}max"),
                     default=None, metavar=axis.upper() if metavars else None, help=text)
        for axis, text in (("k", k_help), ("mu", mu_help))))


def given_options(names: Iterable[str]) -> list[str]:
    """The options among the parameters ``names`` of the running command that the command line
    (or the environment) gave, as flags (``--half-width``), in the order of ``names``."""
    from click.core import ParameterSource

    ctx = click.get_current_context()
    return [f"--{name.replace('_', '-')}" for name in names
            if ctx.get_parameter_source(name) in (ParameterSource.COMMANDLINE, ParameterSource.ENVIRONMENT)]
