"""Sphinx configuration of roughcontact's documentation site (``make docs``).

The toolchain is the one the field's Python libraries use (SciPy, SurfaceTopography,
ContactMechanics): Sphinx, with

* ``autodoc`` + ``autosummary`` for the API reference, one page per public name, generated from
  the docstrings (``_ext/api_pages.py`` writes a page per subpackage from its ``__all__``);
* ``numpydoc`` to read the numpy-style docstrings, as NumPy and SciPy do (Sphinx's own
  ``napoleon`` misreads a property whose first line holds a colon as "type: description");
* ``myst_parser`` for the theory pages, which stay Markdown, readable on GitHub too;
* MathJax served from a local copy (``_ext/offline_mathjax.py``, the files of
  ``sphinx-mathjax-offline``): the site builds and is read without a network;
* ``sphinx-gallery`` for the gallery, whose scripts run at every build, so each example is a test;
* ``_ext/cli_reference.py``, the command-line reference written from the parsers themselves.

The build treats every warning as an error (``make docs``: ``-W --keep-going``), and
``nitpicky`` makes an unresolved cross-reference to roughcontact's own API a warning; names of
other libraries (numpy, xarray, matplotlib) are not linked, since their inventories would need a
network.
"""

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

from roughcontact import __version__  # noqa: E402

project = "roughcontact"
author = "roughcontact developers"
copyright = "2026, roughcontact developers"
version = release = __version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx.ext.mathjax",
    "offline_mathjax",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "api_pages",
    "cli_reference",
]

root_doc = "index"
exclude_patterns = [
    "_build",
    "scripts",
    "gallery_scripts",
    "gallery/*.py",
    "gallery/*.ipynb",
    "gallery/*.zip",
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
templates_path = ["_templates"]

myst_enable_extensions = ["dollarmath", "amsmath", "deflist"]
myst_heading_anchors = 3

autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_typehints = "none"  # the numpy docstrings say the types and units in words
autodoc_member_order = "bysource"
numpydoc_show_class_members = False  # autosummary lists them
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False  # types as words ("ndarray of bool, shape (n, m)")

nitpicky = True
nitpick_ignore_regex = [  # types written as words in numpy docstrings: not names to link
    (r"py:class", r".*[\s{}\"'^/+*()<>,\[\]-].*"),
    (r"py:class", r"[a-z_]+|[0-9.]+|True|False|None|inf"),
    (r"py:.*", r"(numpy|np|xarray|xr|matplotlib|scipy|pandas|dask|pathlib|collections|typing)\..*"),
    (r"py:.*", r"(ndarray|array_like|array|float|int|str|bool|dict|list|tuple|None|callable|Path|optional)"),
    (r"py:.*", r".*\bof\b.*"),  # "ndarray of bool", "list of str"
]

sphinx_gallery_conf = {
    "examples_dirs": "gallery_scripts",
    "gallery_dirs": "gallery",
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "write_computation_times": False,  # its page loads DataTables from CDNs: not offline
    "image_scrapers": ("figure_scraper",),  # _ext/figure_scraper.py
}

html_theme = "alabaster"
html_title = f"roughcontact {version}"
html_static_path = []
html_theme_options = {"description": "Contact mechanics of rough surfaces from measured topographies"}
