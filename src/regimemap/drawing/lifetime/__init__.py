"""The figures of a caisson's sliding over its design life.

The exceedance figure of one lifetime result (:mod:`.exceedance`), the design
chart, ESD against width (:mod:`.chart`), and their shared look (:mod:`.style`).
"""
