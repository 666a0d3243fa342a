"""Sphinx configuration of the regimemap documentation site (``make docs``).

Built offline, warnings as errors (``-W --keep-going``): the pages in MyST
markdown (the notes ``derivation.md``, ``errata.md``, ``waves.md``,
``dynamics.md`` and ``lifetime.md`` among them), the gallery
(``examples/``, run by sphinx-gallery at every build), the API reference
(autosummary's pages from ``_templates/autosummary/api.rst``, a page per
public package and module, whose entries ``_ext/regimemap_api.py`` computes;
autodoc + numpydoc), the architecture's picture (drawn from the code by
``_ext/regimemap_architecture.py``), the command-line reference (sphinx-click)
and the design-file reference (generated from the reader's own tables by
``_ext/regimemap_docs.py``).  ``make docs`` also runs
the ``doctest`` builder: every ``>>>`` example of the pages and of the
docstrings shown in the API reference.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

import regimemap  # noqa: E402

# -- project ---------------------------------------------------------------------------------

project = "regimemap"
author = "regimemap developers"
copyright = "regimemap developers, MIT licence"
release = regimemap.__version__
version = ".".join(release.split(".")[:2])

# -- extensions ------------------------------------------------------------------------------

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.doctest",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "sphinx_click",
    "sphinx_copybutton",
    "sphinx_gallery.gen_gallery",
    "regimemap_docs",
    "regimemap_api",
    "regimemap_architecture",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = [
    "_build",
    "**.ipynb_checkpoints",
    # sphinx-gallery's sources; their pages are auto_examples/
    "examples",
    "auto_examples/**/*.ipynb",
    "auto_examples/**/*.py",
    "auto_examples/**/*.md5",
    "auto_examples/**/*.codeobj.json",
    "auto_examples/**/*.zip",
    "sg_execution_times.rst",
    # text that a package's API page includes (docs/_ext/regimemap_api.py)
    "api/intro",
    # the pictures drawn from the code when the pages are built (docs/_ext/regimemap_architecture.py)
    "_generated",
]
# quotes and ellipses, but not dashes: "--gamma" in the command-line examples stays two hyphens
smartquotes_action = "qe"

# Warnings are errors (make docs: -W --keep-going).  Python cross-references that
# do not resolve (types from numpy, matplotlib ... in the signatures) are not
# warnings (nitpicky off); regimemap_docs reports a broken one in the hand-written
# pages (the guide, the index) instead.
nitpicky = False

# -- MyST ------------------------------------------------------------------------------------

myst_enable_extensions = [
    "dollarmath",   # $...$ and $$...$$ (docs/lifetime.md)
    "amsmath",
    "colon_fence",
    "deflist",
    "attrs_inline",
]
myst_heading_anchors = 3       # [text](waves.md#7-the-equivalent-loaded-block-...) links
myst_dmath_double_inline = True

# MathJax: the copy in the docs' dependencies (django-static-mathjax, MathJax 3, copied into
# _static/mathjax by regimemap_docs), so that the equations render without a network; the
# default CDN otherwise.
from regimemap_docs import MATHJAX_DIR, MATHJAX_FILE, local_mathjax  # noqa: E402

if local_mathjax() is not None:
    mathjax_path = f"{MATHJAX_DIR}/{MATHJAX_FILE}"

# -- autodoc and numpydoc --------------------------------------------------------------------

autodoc_member_order = "bysource"
autodoc_typehints = "signature"
autodoc_preserve_defaults = False
autodoc_default_options = {"show-inheritance": False}
numpydoc_show_class_members = False     # no autosummary tables of each class's members
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
numpydoc_xref_param_type = False

# -- autosummary: the API pages ---------------------------------------------------------------

from regimemap_api import api_context  # noqa: E402

templates_path = ["_templates"]
autosummary_generate = True
# every public package a page (docs/api/index.md lists them) with its modules below it; the
# template (_templates/autosummary/api.rst) reads what regimemap_api finds in the code
autosummary_context = api_context()

# -- doctest ---------------------------------------------------------------------------------

doctest_global_setup = """
import numpy as np
import regimemap
"""
doctest_test_doctest_blocks = "default"   # the >>> blocks of docstrings shown by autodoc too

# -- gallery ---------------------------------------------------------------------------------

sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    # every script runs in a fresh build (as in CI; a failing one fails the build); an
    # incremental build runs again only the scripts that changed (rm -rf docs/auto_examples)
    "filename_pattern": r"/plot_",
    "only_warn_on_example_error": False,
    "abort_on_example_error": False,
    "within_subsection_order": "FileNameSortKey",
    # the library draws on matplotlib Figures without pyplot: this scraper finds them.
    # A new section of the gallery is a new folder of examples/ with a README.rst (the
    # folders sort by name: 08_explorer would come after the lifetime charts).
    "image_scrapers": ("regimemap_docs.figure_scraper",),
    "reset_modules": ("matplotlib",),
    "capture_repr": ("_repr_html_", "__repr__"),
    "ignore_repr_types": r"matplotlib\.",
    "download_all_examples": False,
    "remove_config_comments": True,
    "show_memory": False,
    "line_numbers": False,
    "default_thumb_file": None,
    "matplotlib_animations": False,
    "copyfile_regex": "",
    "plot_gallery": "True",
}
# -D plot_gallery=0 builds the pages without running the gallery (its pictures are then missing)

# -- HTML ------------------------------------------------------------------------------------

html_theme = "pydata_sphinx_theme"
html_title = f"regimemap {release}"
html_static_path = ["_static"]
html_css_files = ["regimemap.css"]
html_show_sourcelink = False
html_theme_options = {
    "navbar_align": "left",
    "show_toc_level": 2,
    "navigation_with_keys": False,
    "header_links_before_dropdown": 6,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version", "theme-version"],
    # offline: no version switcher, no external icons fetched at build time
    "icon_links": [],
}
html_context = {"default_mode": "light"}
html_sidebars = {"index": []}

copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True
