"""Warnings for valid but implausible design files (likely unit slips), and ``--strict``.

The checks are :func:`regimemap.io.plausibility.implausible_values`; here they
become one warning line each on standard error, or, with ``--strict``, a usage
error (exit 2) naming the first.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import click

if TYPE_CHECKING:  # pragma: no cover
    from regimemap.io.design import Design
    from regimemap.waves import CaissonAnalysis

__all__ = ["STRICT_HELP", "check_plausible"]

STRICT_HELP = ("Refuse a design file whose values are valid but implausible for a breakwater "
               "(likely unit slips: a depth over 100 m, a section heavier than 30 kN/m^3 ...); "
               "without it they are warnings on standard error.")


def check_plausible(design: Design, analysis: CaissonAnalysis | None, strict: bool, source: str,
                    param_hint: str = "'DESIGN.toml'") -> None:
    """Warn about (or, with ``strict``, refuse) the implausible values of ``design``.

    ``param_hint`` names the design file's argument or option in the usage error of
    ``strict`` (``'DESIGN.toml'``, or ``'--design'`` for ``regimemap simulate``).
    """
    from ..io.plausibility import implausible_values

    found = implausible_values(design, analysis)
    if not found:
        return
    if strict:
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        raise click.BadParameter(f"{source}: {found[0]}{more}; --strict refuses implausible values",
                                 param_hint=param_hint)
    for item in found:
        click.echo(f"regimemap: warning: {source}: {item}", err=True)
