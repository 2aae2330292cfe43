"""What the cached stages of every tire model share: the default frequency grid and the fit tolerance."""

from __future__ import annotations

from ..tire.model import DEFAULT_FREQS

#: Relative RMS error every fit must meet when the order is chosen automatically.
FIT_TOLERANCE = 0.01

__all__ = ["DEFAULT_FREQS", "FIT_TOLERANCE"]
