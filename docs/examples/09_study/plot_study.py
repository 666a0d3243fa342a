"""
A breakwater in three sections under a sea-level rise
=====================================================

The example study (``regimemap study --example``): a trunk in 8 m and in 12 m of
water with fixed widths, a roundhead in 18 m whose width is found for an expected
sliding distance (ESD) of 0.1 m, each under today's climate and under a sea level
rising linearly to 1 m by the fiftieth service year.  Here with 200 lifetimes a
task (the example has 2000), in this process; every task on its section's own
random numbers, the same under both scenarios, so the scenarios are compared on
the same storms.

Command line::

    regimemap study --example > breakwater.toml
    regimemap study breakwater.toml --jobs 2 -o esd.png -o table.nc
    regimemap study breakwater.toml --resume --figure years --section "trunk 8 m" -o years.png
    regimemap study breakwater.toml --resume --figure width -o width.png
"""

from regimemap.study.figures import study_figure
from regimemap.study.file import parse_study
from regimemap.study.file_example import example_study_text
from regimemap.workflows import run_study

text = example_study_text().replace("trials = 2000 ", "trials = 200 ")
record = run_study(parse_study(text, "breakwater.toml"))
for r in record.rows:
    years = ", ".join(f"{x:g} m in year {y}" for x, y in r.passes if y is not None) or "no limit"
    print(f"{r.section:11s} {r.scenario:20s} b = {r.width:5.2f} m  ESD {r.expected_sliding:.3f} m  "
          f"passes {years}")

# %%
# The expected sliding distance along the breakwater: a line per scenario through
# each section's first width (the narrowest), its other widths as open markers,
# bars of two standard errors, the tolerable limits of Goda & Takagi (0.1 m) and
# Shimosako & Takahashi (0.3 m).  A triangle at the bottom is a width at which no
# lifetime slid.

fig = study_figure(record, "chainage")

# %%
# The expected cumulative sliding of the 8 m trunk (12 m wide) by service year:
# the rise makes the depth-limited waves at the wall higher every year, and the
# expected sliding passes the limits within the life (the years in the key).

fig_years = study_figure(record, "years", section="trunk 8 m")

# %%
# The roundhead's width for an ESD of 0.1 m under each scenario, with its Monte
# Carlo interval: with 200 lifetimes a task the interval is wide; the study's own
# 2000 narrow it by about three.

fig_width = study_figure(record, "width")
