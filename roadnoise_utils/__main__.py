"""``python -m roadnoise_utils``: reproduce everything (every notebook, the figures, the claims report)."""

import sys

from .repro.reproduce import main

sys.exit(main())
