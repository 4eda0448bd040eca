"""The Hertz ellipticity's start table is built safely when two threads need it first at once
(two study chunks solving side by side, issue 34: a list extended in place held four items)."""

from __future__ import annotations

import threading

import numpy as np

from bearingkit.physics.contact import hertz


def test_start_table_built_by_several_threads_at_once(monkeypatch):
    monkeypatch.setattr(hertz, "_START_TABLE", None)
    barrier = threading.Barrier(4, timeout=20)
    tables, errors = [], []

    def build():
        try:
            barrier.wait()
            tables.append(hertz._start_table())
        except Exception as exc:  # reported below
            errors.append(exc)

    threads = [threading.Thread(target=build) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    assert not errors and len(tables) == 4
    for f_grid, u_grid in tables:
        assert f_grid.shape == u_grid.shape == tables[0][1].shape
        np.testing.assert_array_equal(f_grid, tables[0][0])
    # the solve that reads it: κ of a ball on a groove (F = 0.9) the same from the rebuilt table
    assert np.isfinite(hertz._exact_kappa(np.array([0.9]))).all()
