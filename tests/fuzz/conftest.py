"""Make the fuzz modules importable (``--import-mode=importlib`` does not touch sys.path)."""

import sys
from pathlib import Path

HERE = str(Path(__file__).resolve().parent)
if HERE not in sys.path:
    sys.path.insert(0, HERE)
