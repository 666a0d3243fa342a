"""
Choosing the threshold: mean residual life and parameter stability
===================================================================

For NDBC buoy 44007: (a) the mean excess of the storm peaks over the threshold
u, with its 90 % interval, straight above a threshold where the generalised
Pareto distribution holds; (b) the GPD shape and (c) the modified scale
sigma - xi u fitted above each u, flat there (Coles 2001, Sect. 4.3.1).  The
dashed line is the default threshold, the 99.5 % quantile.

Command line::

    regimemap climate ndbc44007_1996-2005_hs_tz.txt --diagnostics threshold.png
"""

from pathlib import Path

from regimemap.climate.analysis import diagnostics
from regimemap.climate.figures import diagnostics_figure
from regimemap.climate.file import read_record
from regimemap.climate.peaks import resolve_threshold


def find_record() -> Path:
    """The full record beside the clone, else the excerpt shipped with the tests."""
    here = Path.cwd()
    for root in (here, *here.parents):
        for candidate in (root.parent / "shared" / "data" / "ndbc44007_1996-2005_hs_tz.txt",
                          root / "tests" / "climate" / "data" / "ndbc44007_1996_hs_tz.txt.gz"):
            if candidate.is_file():
                return candidate
    raise FileNotFoundError("no NDBC 44007 record")


record = read_record(find_record())
found = diagnostics(record)
fig = diagnostics_figure(found, resolve_threshold(record))
