"""Caissons and climates shared by the lifetime tests."""

from __future__ import annotations

from regimemap.lifetime import Caisson, Climate, Errors, LifetimeModel

#: Goda's worked upright breakwater (Goda 2000, Sect. 4.2; `regimemap caisson --example`):
#: in the surf zone (h = 10.1 m), sliding safety factor 1.16 under H0' = 6.3 m.
GODA = Caisson(depth=10.1, armour_depth=5.6, seabed_slope=0.01, width=15.0, base_depth=7.1, crest=3.4,
               friction=0.6, buoyant_weight=2312e3, berm_width=8.0, angle_deg=15.0)

#: The example's climate: H0'_10 = 5.0 m, H0'_50 = 6.3 m (Weibull, k = 2, one storm a year).
CLIMATE = Climate.from_return_values(5.0, 6.3)

MODEL = LifetimeModel(CLIMATE)

#: A narrow caisson that slides in most lifetimes (many sliding waves: the statistics are tame).
NARROW = GODA.with_width(11.0)

NO_ERRORS = Errors.none()
