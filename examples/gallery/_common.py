"""Shared by the gallery examples: where figures go and a matplotlib figure without a display."""

from __future__ import annotations

import os
from pathlib import Path


def out_dir(name: str) -> Path:
    """Folder for an example's figures: $BEARINGKIT_GALLERY_OUT (the docs build) or out/gallery/<name>."""
    folder = Path(os.environ.get("BEARINGKIT_GALLERY_OUT") or Path("out") / "gallery" / name)
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def figure(width: float = 6.4, height: float = 3.6):
    """A matplotlib Figure and Axes drawn off-screen (Agg)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    return fig, fig.add_subplot()
