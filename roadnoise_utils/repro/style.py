"""House style of the notebooks: figure look, print options, table display."""

from __future__ import annotations

import matplotlib as mpl
import numpy as np
import pandas as pd


def set_style() -> None:
    """Set the figure style and print options; call it in the first code cell of every notebook."""
    mpl.rcParams.update(
        {
            "figure.figsize": (8.0, 4.5),
            "figure.dpi": 100,
            "savefig.dpi": 120,
            "savefig.bbox": "tight",
            "axes.grid": True,
            "grid.alpha": 0.3,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "axes.titlesize": 11,
            "axes.labelsize": 10,
            "legend.fontsize": 9,
            "legend.frameon": False,
            "xtick.labelsize": 9,
            "ytick.labelsize": 9,
            "image.cmap": "viridis",
            "figure.constrained_layout.use": True,
        }
    )
    np.set_printoptions(precision=4, suppress=True, linewidth=100)
    pd.set_option("display.precision", 3)
    pd.set_option("display.width", 120)
    pd.set_option("display.max_columns", 12)
