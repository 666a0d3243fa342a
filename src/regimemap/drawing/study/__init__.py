"""The figures of a whole breakwater (``regimemap study``): the expected sliding distance along the
chainage, one section's sliding by service year and the width for the target along the chainage,
a line per climate scenario (:mod:`regimemap.drawing.study.figures`), and the scenarios' look
(:mod:`regimemap.drawing.study.style`)."""
