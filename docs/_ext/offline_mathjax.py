"""Sphinx extension: MathJax served from the site itself, so equations render without a network.

The MathJax 3 files come from the ``sphinx-mathjax-offline`` distribution (a declared ``docs``
dependency), whose own extension module cannot be imported (its folder is named with hyphens);
this one copies the same files into ``_static/mathjax`` of the built site and points Sphinx's
``mathjax`` extension at them.
"""

from __future__ import annotations

from importlib.metadata import distribution
from pathlib import Path

from sphinx.util.fileutil import copy_asset


def mathjax_folder() -> Path:
    """Return the folder of the MathJax files installed with ``sphinx-mathjax-offline``."""
    return Path(distribution("sphinx-mathjax-offline").locate_file("sphinx-mathjax-offline/static/mathjax"))


def copy_mathjax(app, error) -> None:
    """Copy MathJax into the built site (Sphinx ``build-finished``, after a successful build)."""
    if error is None and app.builder.format == "html":
        copy_asset(str(mathjax_folder()), str(Path(app.outdir) / "_static" / "mathjax"))


def setup(app):
    """Point ``mathjax_path`` at the local copy and register the copying."""
    if not (mathjax_folder() / "tex-chtml.js").is_file():
        raise RuntimeError(f"MathJax not found at {mathjax_folder()}: pip install sphinx-mathjax-offline")
    app.config.mathjax_path = "mathjax/tex-chtml.js"
    app.connect("build-finished", copy_mathjax)
    return {"parallel_read_safe": True, "version": "1"}
