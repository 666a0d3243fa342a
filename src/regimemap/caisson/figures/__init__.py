"""The one-page design sheet of a caisson: its layout, its panels and its map.

The page and its title block (:mod:`.page`), the panels (:mod:`.panels`) and
panel (d), the loaded map of the design wave (:mod:`.map_panel`).
"""
