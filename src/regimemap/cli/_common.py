"""Options, validation and error handling shared by the commands.

One module of some length: every command imports its options and its error handling from
this one place, so that they read and fail alike."""

from __future__ import annotations

import contextlib
import functools
import gc
import os
import sys
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar, overload

import click

from ..mechanics.validation import (
    GAMMA_MAX,
    GAMMA_MIN,
    LOAD_LIMITS,
    MAX_AXIS,
    check_gamma,
    check_kprime,
    check_loads,
    check_positive,
    check_resolution,
)
from ..process import INTERRUPTED, TERMINATED, exit_now, flush_on_exit
from ._signals import EXIT_DEADLINE, Terminated, stop_signals

if TYPE_CHECKING:  # pragma: no cover
    from click.decorators import FC

    from ..mechanics.notices import Notice

    #: Base of the option types.  Recent click makes ParamType generic in the
    #: converted value; click 8.1 cannot subscript it at run time.
    ParamType = click.ParamType[Any]
else:
    ParamType = click.ParamType

__all__ = [
    "CONTEXT_SETTINGS",
    "gamma_option",
    "kprime_option",
    "LOAD_OPTIONS",
    "load_options",
    "load_range",
    "check_load_value",
    "check_kprime_crest",
    "positive_float",
    "resolution_type",
    "output_path",
    "output_dir",
    "echo_notices",
    "run_main",
    "RunError",
    "Terminated",
    "stop_signals",
    "gc_paused_at_start",
    "import_matplotlib",
    "ParamType",
    "report_written",
]

CONTEXT_SETTINGS = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


class RunError(click.ClickException):
    """A failure while running (exit code 1), printed as one line."""

    exit_code = 1


class _Checked(ParamType):
    """A click type that validates with one of regimemap.validation's checks."""

    def __init__(self, name: str, check: Callable[[Any], Any], allowed: str = "a number"):
        self.name = name
        self._check = check
        self._allowed = allowed

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        number: Any = value
        if isinstance(value, str):
            try:
                number = float(value)
            except ValueError:
                self.fail(f"{self.name} must be {self._allowed}, got {value!r} (not a number)",
                          param, ctx)
        try:
            return self._check(number)
        except ValueError as exc:
            # the message names the parameter, the range and the value as typed;
            # click prefixes the option name
            if isinstance(value, str):
                self.fail(f"{self.name} must be {self._allowed}, got {value!r}", param, ctx)
            self.fail(str(exc), param, ctx)


GAMMA = _Checked("gamma", check_gamma, f"a finite number in [{GAMMA_MIN:g}, {GAMMA_MAX:g}]")
KPRIME = _Checked("kprime", check_kprime, "a number in [-1, 1]")


def positive_float(name: str, hi: float = MAX_AXIS) -> ParamType:
    """A click type for a finite float in (0, hi] (default: MAX_AXIS, for axis limits)."""
    return _Checked(name, lambda v: check_positive(name, v, hi), f"a finite number > 0 (at most {hi:g})")


class _Resolution(ParamType):
    name = "integer"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> int:
        try:
            return check_resolution("resolution", value)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


resolution_type = _Resolution()


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
     "Radius of gyration about C over B, i > 0 (default: the uniform block, "
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
    return _Checked(name, lambda v: check_load_value(name, v), load_range(name))


class _LoadValues(ParamType):
    """A list ``a,b,c`` or a range ``start:stop:count`` of one load (atlas, animate)."""

    def __init__(self, name: str, max_count: int):
        self.name = f"{name}-list"
        self._what = name
        self._max = max_count

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, list):
            return value
        from ..maps.sweeps import parse_values

        try:
            return parse_values(str(value), self._what, lambda v: check_load_value(self._what, v),
                                self._max)
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
        return f(*args, loads=loads, **kwargs)

    out: Callable[..., Any] = wrapper
    for name, option, metavar, text in reversed(LOAD_OPTIONS):
        kind: ParamType = _load_type(name) if sweep is None else _LoadValues(name, sweep)
        if sweep is not None:
            metavar, text = "LIST", text + " A list a,b,c or a range start:stop:count sweeps it."
        out = click.option(option, name, type=kind, default=None, metavar=metavar,
                           help=text)(out)
    return out


def output_path(path: str | os.PathLike[str], param: str = "--output") -> Path:
    """Check that the folder of ``path`` exists and is writable; raise a usage error if not."""
    from ..io.atomic import check_output_path

    try:
        return check_output_path(path, param)
    except ValueError as exc:
        raise click.BadParameter(str(exc).replace(f"{param} ", "", 1), param_hint=f"'{param}'") from None


def report_written(path: str | os.PathLike[str], note: str | None = None) -> None:
    """Report a written file the one way every command does: its path on standard output.

    A ``note`` about it (frames, points ...) goes to standard error, so that
    ``$(regimemap ...)`` captures the path alone.
    """
    click.echo(os.fspath(path))
    if note:
        click.echo(f"regimemap: {note}", err=True)


def echo_notices(notices: Iterable[Notice], prefix: dict[str, str] | None = None, *,
                 source: str | None = None) -> None:
    """Notices on standard error, one line each: ``regimemap: warning: MESSAGE`` -- the one
    printer of every command's warnings.

    ``prefix`` gives another start of the line to the notices of some codes
    (``{"crammed": "regimemap: note: "}``); ``source`` (a design file's name) goes before
    each message: ``regimemap: warning: SOURCE: MESSAGE``.
    """
    where = f"{source}: " if source else ""
    for n in notices:
        click.echo(f"{(prefix or {}).get(n.code, 'regimemap: warning: ')}{where}{n.message}", err=True)


def _one_line(text: str) -> str:
    """``text`` on one line (newlines and runs of blanks become one space)."""
    return " ".join(str(text).split())


def _say(message: str) -> None:
    try:
        click.echo(_one_line(message), err=True)
    except (OSError, ValueError):  # pragma: no cover - stderr closed
        pass


def _error_message(exc: BaseException) -> str:
    if isinstance(exc, OSError) and exc.strerror:
        where = exc.filename if exc.filename is not None else None
        return f"{exc.strerror}: {str(where)!r}" if where is not None else exc.strerror
    return str(exc) or type(exc).__name__


def output_dir(path: str | os.PathLike[str], param: str = "--out", *, create: bool = False) -> Path:
    """Check that ``path`` is an existing folder where files can be created; usage error if not.

    With ``create``, a missing folder whose parent exists (and accepts new
    files) is created first; a missing parent is still a usage error.

    Like :func:`output_path` for a folder: the check creates and removes an
    empty hidden file, since permission bits do not tell (root, read-only or
    virtual file systems such as /proc).
    """
    from ..io.atomic import folder_problem

    p = Path(path)
    if not str(path).strip():
        raise click.BadParameter(f"must be a folder, got {str(path)!r}", param_hint=f"'{param}'")
    if p.exists() and not p.is_dir():
        raise click.BadParameter(f"{str(path)!r} is a file, not a folder", param_hint=f"'{param}'")
    if not p.is_dir() and create:
        parent = p.parent if str(p.parent) else Path(".")
        if parent.is_dir() and not folder_problem(parent):
            try:
                p.mkdir()
            except FileExistsError:
                pass
            except OSError as exc:
                raise click.BadParameter(f"cannot create folder {str(path)!r}: {exc.strerror}",
                                         param_hint=f"'{param}'") from None
    if not p.is_dir():
        hint = " (its parent folder must exist)" if create else ""
        raise click.BadParameter(f"folder {str(path)!r} does not exist{hint}",
                                 param_hint=f"'{param}'")
    problem = folder_problem(p)
    if problem:
        raise click.BadParameter(f"folder {str(path)!r} {problem}", param_hint=f"'{param}'")
    return p


# -- start-up: the cyclic garbage collector -------------------------------------------------
#
# ``regimemap plot`` is a short process that spends most of its time importing
# matplotlib, which allocates ~120 000 long-lived objects.  With the collector
# running, CPython scans them again and again while they are being created
# (~35-40 ms of a 0.6 s run, measured with gc.callbacks).  ``cli.main``
# therefore pauses the collector at start; a drawing command calls
# :func:`import_matplotlib`, which imports matplotlib, freezes what the imports
# allocated (``gc.freeze``: later collections skip it) and resumes collecting,
# so commands that draw many figures (figures, atlas, animate) still free their
# garbage.  Library users and click's test runner are not affected.

_gc_state = {"paused": False, "frozen": False, "may_freeze": False}


@contextlib.contextmanager
def gc_paused_at_start() -> Iterator[None]:
    """Pause the cyclic GC until :func:`import_matplotlib` (or the end); restore it after."""
    was_enabled = gc.isenabled()
    gc.disable()
    _gc_state["paused"] = was_enabled  # a caller that disabled it keeps it disabled
    # gc.unfreeze() cannot tell whose objects it thaws: freeze only if nobody else has
    _gc_state["may_freeze"] = gc.get_freeze_count() == 0
    try:
        yield
    finally:
        if _gc_state["frozen"]:
            gc.unfreeze()
        _gc_state["paused"] = _gc_state["frozen"] = False
        if was_enabled:
            gc.enable()


def import_matplotlib() -> None:
    """Import matplotlib and its Agg canvas for a drawing command; then resume the GC.

    The renderer imports matplotlib lazily; a drawing command calls this first
    so that the import happens while the collector is paused (see above).
    """
    from ..drawing import load_matplotlib

    load_matplotlib()

    if _gc_state["paused"]:
        _gc_state["paused"] = False
        if _gc_state["may_freeze"]:
            gc.freeze()
            _gc_state["frozen"] = True
        gc.enable()


def _guess_path(group: click.Command, argv: list[str] | None) -> str:
    """``regimemap CMD`` from the arguments, for usage errors click reports without a context."""
    args = sys.argv[1:] if argv is None else argv
    commands = getattr(group, "commands", {})
    for a in args:
        if a in commands:
            return f"regimemap {a}"
        if not a.startswith("-"):
            break
    return "regimemap"


def _stopped(how: tuple[str, int], exiting: bool) -> int:
    """The end of an interrupted command: its one line and exit code.  ``exiting`` (the
    ``regimemap`` process): the process ends here, without the interpreter's teardown
    (:func:`regimemap.process.exit_now`; every cleanup of the command has run)."""
    line, code = how
    if exiting:
        exit_now(code, _one_line(line))
    _say(line)
    return code


def run_main(group: click.Command, argv: list[str] | None = None, *, exiting: bool = False) -> int:
    """Run ``group`` and return an exit code; no traceback ever reaches the user.

    Every error is one line on stderr:

    * usage errors (bad option or value, unknown command) exit 2:
      ``regimemap plot: error: Invalid value for '--gamma': ... (see 'regimemap plot --help')``;
    * failures while running (:class:`RunError`, ``ValueError``, ``OSError``)
      exit 1: ``regimemap: error: ...``;
    * an unexpected exception (a bug) exits 1 with ``regimemap: internal error: ...``
      (set ``REGIMEMAP_DEBUG=1`` to see the traceback);
    * an interrupt (Ctrl-C, SIGINT) exits 130 with ``regimemap: interrupted``,
      SIGTERM 143 with ``regimemap: terminated`` (128 + the signal's number, as
      a shell reports a process the signal ended); worker processes are
      stopped and no file is left half-written (:func:`._signals.stop_signals`; with
      ``exiting``, the process ends here, at the latest 1.5 s after the signal, and a
      second signal is ignored).
    """
    if exiting:
        flush_on_exit(sys.stdout, sys.stderr)
    try:
        with stop_signals(exiting=exiting, deadline=EXIT_DEADLINE if exiting else None):
            # without standalone mode click returns the code of a click.exceptions.Exit (--check's 1)
            code = group.main(args=argv, prog_name="regimemap", standalone_mode=False)
    except Terminated:
        return _stopped(TERMINATED, exiting)
    except click.exceptions.Abort:
        return _stopped(INTERRUPTED, exiting)
    except click.UsageError as exc:
        path = exc.ctx.command_path if exc.ctx is not None else _guess_path(group, argv)
        _say(f"{path}: error: {exc.format_message()} (see '{path} --help')")
        return exc.exit_code
    except click.ClickException as exc:
        _say(f"regimemap: error: {exc.format_message()}")
        return exc.exit_code
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except KeyboardInterrupt:
        return _stopped(INTERRUPTED, exiting)
    except BrokenPipeError:
        return 1
    except (ValueError, OSError) as exc:
        _say(f"regimemap: error: {_error_message(exc)}")
        return 1
    except Exception as exc:  # a bug; still one line, no traceback
        if os.environ.get("REGIMEMAP_DEBUG"):
            raise
        _say(f"regimemap: internal error: {type(exc).__name__}: {exc}"
             " (please report it; REGIMEMAP_DEBUG=1 shows the traceback)")
        return 1
    return code if isinstance(code, int) and not isinstance(code, bool) else 0
