"""The commented example design file (Goda's worked upright breakwater, with a life of 50 years)."""

from __future__ import annotations

__all__ = ["example_design_text"]

_EXAMPLE = """\
# regimemap design file: Goda's worked upright breakwater
# (Goda 2000, Random Seas and Design of Maritime Structures, Sect. 4.2).
# SI units: metres, seconds, degrees, kg/m^3; weights in kN per metre of breakwater.
# Expected: H1/3 = 5.80 m, Hmax = 8.05 m, p1 = 97.6 kPa, P = 941 kN/m,
#           U = 493 kN/m, SF sliding = 1.16, SF overturning = 2.56.

{tables}# Optional: the sliding of the caisson over its design life (`regimemap lifetime`), the
# expected sliding distance (ESD) of Shimosako & Takahashi (1999) by Monte Carlo: storms
# from the climate below, Rayleigh waves in each, the slide of every wave (docs/lifetime.md).
# The caisson, its site and the wave's angle are those above; the storms replace the design
# wave. Only the climate is required: H0_10 and H0_50, or annual_maxima.
{lifetime}
# The uncertainty factors, each ratio (1 + cov z) with z standard normal: [ratio, cov] (the
# mean factor and its coefficient of variation; Takayama & Ikeda 1992 as cited by Shimosako &
# Takahashi 1999, docs/lifetime.md, Sect. 7). A factor left out takes this default.
[lifetime.errors]
{errors}"""

def example_design_text() -> str:
    """The commented example design file (Goda's worked upright breakwater, with a life of 50 years).

    Its ``[site]``, ``[wave]``, ``[caisson]`` and ``[lifetime]`` are the example lines of their
    keys (:func:`~regimemap.caisson.file_keys.example_tables`,
    :func:`~regimemap.io.toml_keys.example_table`); its ``[lifetime.errors]`` are the defaults of
    :data:`regimemap.lifetime.DEFAULT_ERRORS`, each with its key's comment.
    """
    from regimemap.lifetime import DEFAULT_ERRORS

    from ..io.toml_keys import example_table
    from ..lifetime.file_keys import ERROR_FACTORS, LifetimeSpec
    from .file_keys import example_tables

    lines = []
    for name, spec in ERROR_FACTORS.items():
        f = getattr(DEFAULT_ERRORS, name)
        lines.append(f"{f'{name} = [{f.ratio!r}, {f.cov!r}]':<30} # {spec.example}\n")
    return (_EXAMPLE.replace("{tables}", example_tables())
            .replace("{lifetime}", example_table("lifetime", LifetimeSpec))
            .replace("{errors}", "".join(lines)))
