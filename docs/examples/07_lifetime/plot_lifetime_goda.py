r"""
Sliding of Goda's caisson over 50 years
=======================================

The Monte Carlo of :doc:`/lifetime` for Goda's worked caisson, 15 m wide:
storms from a Weibull climate with H\ :sub:`0`\ ′ = 5.0 m and 6.3 m at 10 and
50 years, Rayleigh waves in each storm and the slide of every wave in closed
form.  (a) The probability that the lifetime sliding exceeds x, with the
largest slide of a single storm, the expected sliding distance (ESD) and the
tolerable limits; (b) the histogram of the lifetimes that slid.

Command line::

    regimemap caisson --example > goda.toml
    regimemap lifetime goda.toml --trials 2000 -o life.png
"""

from regimemap.lifetime import Caisson, Climate, LifetimeModel, lifetime_sliding
from regimemap.lifetime.figures.exceedance import lifetime_figure

goda = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1, crest=3.4,
               friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)
model = LifetimeModel(Climate.from_return_values(5.0, 6.3))
result = lifetime_sliding(goda, model, trials=2000, seed=2026)
print(f"ESD = {result.expected_sliding:.3f} ± {result.std_error:.3f} m; "
      f"{result.never_slides:.0%} of the lifetimes never slide")

fig = lifetime_figure(result)
