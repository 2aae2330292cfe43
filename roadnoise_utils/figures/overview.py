"""Figures of notebook 00-overview: the RM pipeline (Fig. 1)."""

from __future__ import annotations

import textwrap

import matplotlib.pyplot as plt
from matplotlib.patches import Rectangle

#: Characters per line of a stage's text: the box is 0.88 of a 1.5-inch column.
BOX_CHARACTERS = 19
#: Box colour of each part of the pipeline (``part`` of a stage in ``data/collection.toml``).
PART_COLOURS = {"frequency": "tab:blue", "validation": "tab:orange", "time": "tab:green"}


def plot_rm_pipeline(stages: list[dict[str, str]]) -> plt.Figure:
    """Fig. 1 analogue: the RM pipeline, stage by stage, with the notebook of each stage.

    ``stages``: the ``[[stage]]`` tables of ``data/collection.toml`` in order
    (:func:`roadnoise_utils.repro.collection.stages`): ``text``, ``notebook``, ``paper`` and
    ``part`` (a key of :data:`PART_COLOURS`).
    """
    fig, ax = plt.subplots(figsize=(1.5 * len(stages), 3.6))
    ax.set_xlim(0, len(stages))
    ax.set_ylim(0, 1)
    ax.axis("off")
    for i, stage in enumerate(stages):
        text, nb, figs = stage["text"], stage["notebook"].split("-")[0], stage["paper"]
        colour = PART_COLOURS[stage["part"]]
        ax.add_patch(Rectangle((i + 0.06, 0.35), 0.88, 0.45, fc=colour, alpha=0.18, ec=colour))
        wrapped = "\n".join(textwrap.fill(line, BOX_CHARACTERS) for line in text.splitlines())
        ax.text(i + 0.5, 0.575, wrapped, ha="center", va="center", fontsize=7.5)
        ax.text(i + 0.5, 0.25, f"notebook {nb}\n{figs}", ha="center", va="center", fontsize=7, color="0.3")
        if i < len(stages) - 1:
            ax.annotate("", (i + 1.06, 0.575), (i + 0.94, 0.575), arrowprops={"arrowstyle": "->", "color": "0.3"})
    ax.text(1.5, 0.93, "frequency domain: FE tire → local transfer functions", ha="center", color="tab:blue")
    ax.text(6.5, 0.93, "time domain: n parallel systems driven by the road", ha="center", color="tab:green")
    fig.suptitle("Fig. 1 analogue: scheme of the RoadNoise (RM) model and where each stage lives")
    return fig
