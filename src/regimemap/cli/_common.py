"""Options, validation and error handling shared by the commands."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any, Callable

import click

from ..validation import check_gamma, check_kprime, check_positive, check_resolution

__all__ = [
    "CONTEXT_SETTINGS",
    "gamma_option",
    "kprime_option",
    "positive_float",
    "resolution_type",
    "output_path",
    "run_main",
    "RunError",
]

CONTEXT_SETTINGS = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


class RunError(click.ClickException):
    """A failure while running (exit code 1), printed as one line."""

    exit_code = 1


class _Checked(click.ParamType):
    """A click type that validates with one of regimemap.validation's checks."""

    def __init__(self, name: str, check: Callable[[Any], Any]):
        self.name = name
        self._check = check

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if not isinstance(value, str):
            return self._check(value)
        try:
            number: Any = float(value)
        except ValueError:
            self.fail(f"{value!r} is not a number", param, ctx)
        try:
            return self._check(number)
        except ValueError as exc:
            # the message names the parameter; click prefixes the option name
            self.fail(str(exc), param, ctx)


GAMMA = _Checked("gamma", check_gamma)
KPRIME = _Checked("kprime", check_kprime)


def positive_float(name: str) -> click.ParamType:
    """A click type for a finite float > 0."""
    return _Checked(name, lambda v: check_positive(name, v))


class _Resolution(click.ParamType):
    name = "integer"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> int:
        try:
            return check_resolution("resolution", value)
        except ValueError as exc:
            self.fail(str(exc), param, ctx)


resolution_type = _Resolution()


def gamma_option(**kwargs: Any) -> Callable:
    """``--gamma`` (aspect ratio H/B > 0)."""
    kwargs.setdefault("required", True)
    return click.option("--gamma", type=GAMMA, help="Aspect ratio gamma = H/B (> 0).",
                        **kwargs)


def kprime_option(**kwargs: Any) -> Callable:
    """``--kprime`` (force height h/H in [-1, 1])."""
    kwargs.setdefault("required", True)
    return click.option("--kprime", type=KPRIME,
                        help="Force height k' = h/H in [-1, 1] (negative below the centre of mass).",
                        **kwargs)


def output_path(path: str | os.PathLike[str], param: str = "--output") -> Path:
    """Check that the folder of ``path`` exists and is writable; raise a usage error if not."""
    from .._atomic import check_output_path

    try:
        return check_output_path(path, param)
    except ValueError as exc:
        raise click.BadParameter(str(exc).replace(f"{param} ", "", 1), param_hint=f"'{param}'")


def run_main(group: click.Command, argv: list[str] | None = None) -> int:
    """Run ``group`` and return an exit code; no traceback ever reaches the user.

    Usage errors exit 2, failures while running exit 1, an interrupt exits 130.
    """
    try:
        group.main(args=argv, prog_name="regimemap", standalone_mode=False)
    except click.exceptions.Abort:
        click.echo("regimemap: interrupted", err=True)
        return 130
    except click.ClickException as exc:
        exc.show()
        return exc.exit_code
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except KeyboardInterrupt:
        click.echo("regimemap: interrupted", err=True)
        return 130
    except BrokenPipeError:
        return 1
    except (ValueError, OSError) as exc:
        click.echo(f"regimemap: error: {exc}", err=True)
        return 1
    except Exception as exc:  # pragma: no cover - a bug; still one line, no traceback
        click.echo(f"regimemap: internal error: {type(exc).__name__}: {exc}", err=True)
        if os.environ.get("REGIMEMAP_DEBUG"):
            raise
        return 1
    return 0
