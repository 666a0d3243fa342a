"""The commented example study (``regimemap study --example``): Goda's breakwater in three sections.

Goda's worked upright breakwater (the design file of ``regimemap caisson --example``,
its tables inline) along a sloping sea bed: the trunk in 8 m and 12 m of water, the
head in 18 m, under today's climate and a sea-level rise of 1 m by year 50.  Sized to
run in well under a minute on two cores.
"""

from __future__ import annotations

__all__ = ["example_study_text"]

_HEAD = """\
# regimemap study file: a breakwater in three sections under two climate scenarios.
# Every section x scenario is a task: `regimemap study THIS.toml --jobs 2` runs them,
# stores each as it finishes (a folder beside this file), and --resume finishes an
# interrupted run to the same numbers. SI units as in a design file.

seed = 2026     # the root seed of every task (each section has its own stream, the same
                # for every scenario: the scenarios are compared on the same storms)
trials = 2000   # lifetimes per task (more for a design: the standard error falls as 1/sqrt)

# The base design: the tables of a design file inline (or base = "design.toml",
# relative to this file). Each [[section]] below changes some of their keys.
"""

_TAIL = """
# The sections along the breakwater, chainage increasing. A key of [site], [caisson] or
# [lifetime] changes the base design for this section (every check of a design file
# applies); width or widths are the widths simulated (the weight W' in proportion to the
# width, as `regimemap lifetime --width`), target (with widths, the bracket) asks for the
# width whose expected sliding distance (ESD) is the target.
[[section]]
name = "trunk 8 m"
chainage = 0.0        # m along the breakwater
depth = 8.0           # [site] depth: the shallow, depth-limited end
armour_depth = 4.5
base_depth = 5.5      # [caisson] base_depth
widths = [12.0, 15.0, 18.0]

[[section]]
name = "trunk 12 m"
chainage = 250.0
depth = 12.0
armour_depth = 7.0
base_depth = 8.5
widths = [18.0, 22.0]

[[section]]
name = "head 18 m"
chainage = 500.0
depth = 18.0
armour_depth = 11.0
base_depth = 12.5
target = 0.1          # the width for ESD = 0.1 m (Goda & Takagi 2000) ...
widths = [20.0, 45.0] # ... searched between these widths
tolerance = 0.5       # to half a metre

# The climate scenarios. None of sea_level_rise (a table year = metres, linear between the
# years from 0 m today, constant after the last; or rate in m/yr and acceleration in
# m/yr^2), wave_height_factor or storm_rate_factor (tables year = factor, from 1 today):
# today's climate.
[[scenario]]
name = "today"

[[scenario]]
name = "rise 1 m by year 50"
sea_level_rise = { 50 = 1.0 }   # the mean sea level of each service year, m above today's
# wave_height_factor = { 50 = 1.05 }  # storms 5 % higher by year 50
# storm_rate_factor = { 50 = 1.2 }    # 20 % more storms by year 50
"""


def example_study_text() -> str:
    """The commented example study file (its base design inline: ``regimemap caisson --example``)."""
    from ..caisson.file_example import example_design_text

    return _HEAD + "\n" + example_design_text().rstrip("\n") + "\n" + _TAIL
