"""The local web app (``bearingkit serve``): open a bearing, edit its operating point, see it analysed.

SI inside; units are parsed only from the form's text (by the input loader). The app is a face: it
calls :func:`bearingkit.pipeline.analyze` and shows the :class:`~bearingkit.pipeline.Analysis` (plots
drawn in the browser from its JSON, or PNGs of :mod:`bearingkit.report.plots`); it computes no physics.

- :mod:`bearingkit.app.form` — the page's state as data → the input document (TOML as a dict);
- :mod:`bearingkit.app.sweep` — one-factor sweeps, batched as load cases of one analysis;
- :mod:`bearingkit.app.store` — recent analyses and the temporary folder downloads are written to;
- :mod:`bearingkit.app.api` — the FastAPI app (:func:`create_app`);
- :mod:`bearingkit.app.server` — :func:`serve`, uvicorn on 127.0.0.1;
- ``static/`` — the page: plain HTML, CSS and JavaScript, no build step, no CDN.
"""

from bearingkit.extras import check

check("app", "the web app (bearingkit.app, bearingkit serve)")  # one line naming the extra, not a traceback

from bearingkit.app.api import create_app  # noqa: E402
from bearingkit.app.server import serve  # noqa: E402

__all__ = ["create_app", "serve"]
