"""Session-wide settings of the test suite.

``BEARINGKIT_BACKGROUND_COMPILE=0``: a small solve while the compiled core is not built would start
``bearingkit compile`` in the background (:func:`bearingkit.rows.numba_cache.start_background_build`);
the tests never leave such a process behind (``make test`` builds the core first, in the foreground).
Subprocesses started by tests inherit the setting.
"""

import os

os.environ.setdefault("BEARINGKIT_BACKGROUND_COMPILE", "0")
