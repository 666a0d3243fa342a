"""Motions after initiation drawn: one run's time history and GIF, and the figures D.1-D.3.

One run (:mod:`.history`); the outcome-map figures of ``regimemap
dynamics-figures`` (:mod:`.presets`).
"""
