"""The regime map drawn: the map and its key, a map on a figure of its own, the report's figures.

The map (:mod:`.mapplot`, recording its artists in :mod:`.artists`), its key
(:mod:`.key`), the overlay of the ambiguous parts (:mod:`.ambiguity`), a map on a
figure of its own (:mod:`.figure`), the report's presets and model figure
(:mod:`.presets`, :mod:`.model`), the worked figures of the loaded block
(:mod:`.worked`), all of them into a folder (:mod:`.batch`), the atlas
(:mod:`.atlas`) and the animation (:mod:`.animation`).
"""
