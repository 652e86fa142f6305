"""Figures drawn for files, without pyplot.

The package's commands and helpers write their figures to PNG, PDF or SVG files. They build them here as plain
matplotlib ``Figure`` objects with an Agg canvas, so that drawing one never selects matplotlib's backend, never opens a
window, and never changes the state of a user's pyplot session (a notebook's inline backend stays as it was). A
figure made here is freed with its last reference; it needs no ``pyplot.close``. In a notebook it still displays as
the cell's value, as any matplotlib ``Figure`` does.
"""

from __future__ import annotations

import sys

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure


def new_figure(**figure_kw) -> Figure:
    """A ``matplotlib.figure.Figure(**figure_kw)`` (``figsize`` in inches, ``dpi`` ...) on its own Agg canvas."""
    fig = Figure(**figure_kw)
    FigureCanvasAgg(fig)
    return fig


def subplots(nrows: int = 1, ncols: int = 1, *, figsize=None, squeeze: bool = True, sharex=False, sharey=False,
             subplot_kw=None, gridspec_kw=None):
    """``pyplot.subplots`` without pyplot: ``(fig, axes)``, with ``axes`` as ``pyplot.subplots`` gives them (one
    ``Axes``, or an array of shape (nrows, ncols), squeezed unless ``squeeze=False``)."""
    fig = new_figure(figsize=figsize)
    axes = fig.subplots(nrows, ncols, squeeze=squeeze, sharex=sharex, sharey=sharey, subplot_kw=subplot_kw,
                        gridspec_kw=gridspec_kw)
    return fig, axes


def release(fig) -> None:
    """Drop ``fig`` from pyplot's figure manager when pyplot made it (a figure a caller drew with pyplot and handed
    to a saving helper); nothing for a figure of this module, and pyplot is never imported for it."""
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close(fig)
