"""
The design sheet of Goda's caisson
==================================

The one-page design sheet (A4) of Goda's worked upright breakwater, the design
file that ``regimemap caisson --example`` prints: (a) the cross-section to
scale, (b) Goda's pressures on the wall and (c) the uplift, (d) the loaded map
with the design point and its path as the wave grows, (e) the safety factors
along that path, (f) the numbers and, as the file has a ``[lifetime]`` table,
(g) the caisson's sliding over its design life.

Command line::

    regimemap caisson --example > goda.toml
    regimemap caisson goda.toml -o sheet.pdf

The command simulates the file's 5000 lifetimes; the docs simulate 2000.
"""

from regimemap.caisson.figures.page import sheet_figure
from regimemap.caisson.file import example_design_text, parse_design
from regimemap.lifetime import lifetime_sliding
from regimemap.caisson.report import caisson_checks, caisson_report, sheet_map
from regimemap.maps.loadedmap import mode_label

design = parse_design(example_design_text(), source="goda.toml")
report = caisson_report(design.analysis_inputs())
a = report.analysis
print(f"P = {float(a.loads.P) / 1e3:.1f} kN/m, SF sliding = {float(a.stability.sliding):.3f}, "
      f"mode on the loaded map: {mode_label(report.mode)}")

life = lifetime_sliding(design.lifetime_caisson(), design.lifetime_model(), trials=2000,
                        seed=design.lifetime_spec().seed)
print(f"expected sliding distance over {life.years} years: {life.expected_sliding:.3f} m")

view, data = sheet_map(report)  # panel (d): its view and the loaded map in it
fig = sheet_figure(report, view=view, data=data, checks=[*caisson_checks(report), *life.checks],
                   title="goda.toml", lifetime=life)
