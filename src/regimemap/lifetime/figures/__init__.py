"""A caisson's design life drawn: the exceedance figure and the design chart.

The sliding over the life and its exceedance curve (:mod:`.exceedance`), the
expected sliding distance against the width (:mod:`.chart`), and what they share:
sizes, the title block, numbers in words (:mod:`.style`); which of the two a run's record
draws (:mod:`.record_figure`).
"""
