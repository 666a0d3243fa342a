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
[lifetime]
years = 50                # design life, years
trials = 5000             # lifetimes simulated (the ESD's standard error falls as 1/sqrt(trials))
seed = 2026               # root seed: the same seed, the same numbers (omit: a fresh seed, reported)
distribution = "weibull"  # storm peaks H0': "weibull" or "gumbel"
shape = 2.0               # Weibull shape k (> 0)
H0_10 = 5.0               # 10-year return value of H0', m
H0_50 = 6.3               # 50-year return value of H0', m (the design wave above)
# annual_maxima = [4.1, 3.6, 5.2, 4.4, 3.9]  # instead of H0_10 and H0_50: observed annual
                          # maxima of H0', m (at least three; Weibull needs shape > 1)
# storms_per_year = 4     # a Poisson number of storms a year (peaks over a threshold;
                          # not with annual_maxima); default: one storm a year, the annual maximum
# record = { path = "buoy.txt", threshold = "99.5%" }  # instead of the climate above: a
                          # measured offshore record and the options of `regimemap climate`
# climate_replicates = 200  # with record: the ESD under 200 bootstrap climates, and its band
storm_hours = 2.0         # duration of each storm's peak sea state, hours
# period = 11.4           # a fixed T1/3 for every storm, s (default: Goda's 3.3 H0'^0.63)
# steepness = 0.035       # or a fixed deep-water steepness H0'/L0 (not with period)
tide_range = 0.0          # tidal range, m: each storm's water level is (range/2) sin(2 pi phase)
thresholds = [0.03, 0.1, 0.3, 1.0, 3.0]  # lifetime slides whose exceedance is reported, m
# truncate = 3.0          # cut the normal error factors at +-3 standard deviations (default: none)
impulsive = false         # Takahashi's impulsive coefficient in each wave's force (default false)
target = 0.1              # the requirement ESD <= target, m (Goda & Takagi 2000; default 0.1)
# allowed = {"0.1" = 0.2, "0.3" = 0.05}  # the largest allowed P(lifetime sliding > x m)
                          # (Kim & Suh 2013; default: none)
# failure_sliding = 5.0   # m the caisson may slide before it is off its mound (the harbour-side
                          # crest width of the mound): P(S > it) is the probability of failure

# The uncertainty factors, each ratio (1 + cov z) with z standard normal: [ratio, cov] (the
# mean factor and its coefficient of variation; Takayama & Ikeda 1992 as cited by Shimosako &
# Takahashi 1999, docs/lifetime.md, Sect. 7). A factor left out takes this default.
[lifetime.errors]
{errors}"""

#: What each uncertainty factor multiplies, for the comments of the example.
_ERROR_COMMENTS = {
    "deepwater": "on the storm's H0' (drawn once per lifetime)",
    "transformation": "on H1/3 at the wall (once per storm)",
    "force": "on the wave force P and the uplift U (once per storm)",
    "friction": "on the friction coefficient (once per storm)",
}


def example_design_text() -> str:
    """The commented example design file (Goda's worked upright breakwater, with a life of 50 years).

    Its ``[site]``, ``[wave]`` and ``[caisson]`` are the example lines of their keys
    (:func:`~regimemap.caisson.file_keys.example_tables`); its ``[lifetime.errors]`` are the
    defaults of :data:`regimemap.lifetime.DEFAULT_ERRORS`.
    """
    from regimemap.lifetime import DEFAULT_ERRORS

    from .file_keys import example_tables

    lines = []
    for name, comment in _ERROR_COMMENTS.items():
        f = getattr(DEFAULT_ERRORS, name)
        lines.append(f"{f'{name} = [{f.ratio!r}, {f.cov!r}]':<30} # {comment}\n")
    return _EXAMPLE.replace("{tables}", example_tables()).replace("{errors}", "".join(lines))
