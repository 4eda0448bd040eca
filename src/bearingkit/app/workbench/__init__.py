"""The workbench: the app's pages beyond the one bearing (docs/app.md).

- :mod:`~bearingkit.app.workbench.catalogue` — browse and filter the catalogue, select by life, compare
  up to four bearings at one operating point;
- :mod:`~bearingkit.app.workbench.systems` — shaft and drivetrain files solved with every bearing;
- :mod:`~bearingkit.app.workbench.studies` — a study of the current bearing, shaft or drivetrain as a
  study file; :mod:`~bearingkit.app.workbench.jobs` runs it in the background;
- :mod:`~bearingkit.app.workbench.duty` — a duty cycle's bins rated and combined by Miner;
- :mod:`~bearingkit.app.workbench.routes` — their HTTP routes (:func:`register`).
"""
