"""sphinx-gallery scraper of the ``matplotlib.figure.Figure`` objects a gallery script holds.

roughcontact's plotting functions build figures without pyplot (no global state), which the
default scraper (pyplot's open figures) does not see. This one saves every Figure found in the
script's module-level variables after each cell, once each, in the order they appear.
"""

from __future__ import annotations

import weakref

_saved: weakref.WeakSet = weakref.WeakSet()


def scrape(block, block_vars, gallery_conf, **kwargs) -> str:
    """Save the new figures of the cell just run; return their reST (sphinx-gallery's scraper API)."""
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst

    figures = {  # by identity: a figure held under two names is saved once
        id(value): value
        for value in block_vars["example_globals"].values()
        if isinstance(value, Figure) and value not in _saved
    }.values()
    paths = []
    for figure, path in zip(figures, block_vars["image_path_iterator"], strict=False):
        figure.savefig(path, dpi=100, bbox_inches="tight")
        _saved.add(figure)
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


def _get_sg_image_scraper():
    """Return :func:`scrape` (how sphinx-gallery finds a scraper named by its module in the config)."""
    return scrape
