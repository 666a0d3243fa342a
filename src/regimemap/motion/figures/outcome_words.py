"""The words of an outcome map: axis labels of the swept inputs, the title, a rotation in degrees."""

from __future__ import annotations

import math
from typing import Any

__all__ = ["AXIS_LABELS", "axis_label", "outcome_title", "rotation_text"]

#: Axis labels by swept input: (physical, dimensionless).
AXIS_LABELS: dict[str, tuple[str, str | None]] = {
    "k_peak": (r"peak force $k_p = F_{max}/(mg)$", r"$k_p\,/\tan\alpha$"),
    "duration": (r"pulse duration $T$ (s)", r"$\omega_p\,/\,p$"),
    "omega_p": (r"pulse frequency $\omega_p$ (rad/s)", r"$\omega_p\,/\,p$"),
    "mu": (r"friction $\mu$", None),
    "kprime": (r"height of the push $k'$", None),
    "gamma": (r"aspect ratio $\gamma = H/B$", None),
    "half_width": (r"half width $B$ (m)", None),
    "gyration": (r"radius of gyration / $B$", None),
    "buoyancy": (r"buoyancy $\beta$ (× $mg$)", None),
    "uplift": (r"uplift $u$ (× $mg$)", None),
    "uplift_ratio": (r"uplift ratio $\nu$ (× $F$)", None),
    "uplift_arm": (r"uplift arm $e_u$ (× $B$)", None),
}


def axis_label(name: str, dimensionless: bool = False, shape: str | None = None) -> str:
    """The axis label of a swept input (mathtext), physical or dimensionless."""
    phys, dim = AXIS_LABELS.get(name, (name, None))
    if dimensionless and dim is not None:
        if name == "duration" and shape is not None:
            cycles = "2\\pi" if shape in ("one-sine", "one-cosine") else "\\pi"
            return dim + rf"  ($\omega_p = {cycles}/T$)"
        return dim
    return phys


_TITLE_NAMES = (("gamma", "γ", ""), ("half_width", "B", " m"), ("mu", "μ", ""), ("kprime", "k'", ""),
                ("k_peak", "k_p", ""), ("duration", "T", " s"), ("omega_p", "ω_p", " rad/s"),
                ("gyration", "r/B", ""), ("buoyancy", "β", ""), ("uplift", "u", ""),
                ("uplift_ratio", "ν", ""), ("uplift_arm", "e_u", ""))


def outcome_title(shape: str, fixed: dict[str, Any], restitution: float | None = None,
                  min_rotation: float = 0.0) -> str:
    """A title naming the pulse and the fixed inputs (plain text), e.g.
    ``half-sine pulse; γ = 3, B = 0.2 m, μ = 5, k' = 0``; with ``min_rotation`` (rad) the
    smallest rotation that counts as rocking."""
    parts = []
    for key, sym, unit in _TITLE_NAMES:
        v = fixed.get(key)
        if v is None or (key in ("buoyancy", "uplift", "uplift_ratio") and v == 0.0):
            continue
        if key == "uplift_arm" and not (fixed.get("uplift") or fixed.get("uplift_ratio")):
            continue
        parts.append(f"{sym} = {v:.4g}{unit}")
    if restitution is not None:
        parts.append(f"restitution {restitution:g}")
    if min_rotation > 0.0:
        parts.append(f"rocking from {rotation_text(min_rotation)}")
    return f"{shape} pulse; " + ", ".join(parts)


def rotation_text(angle: float) -> str:
    """An angle (rad) in degrees for people: ``0.1°``."""
    return f"{math.degrees(angle):.3g}°"
