"""The figures of a wave record's extremes (:mod:`regimemap.drawing.climate.figures`): the record
with its storm peaks, the return levels with their bootstrap band and the observations, the QQ
plot, and the threshold diagnostics (mean residual life, parameter stability)."""
