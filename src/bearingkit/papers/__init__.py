"""The four seed papers reproduced by bearingkit: one sub-package per paper (first author and year).

SI units throughout. Each paper's package holds what is specific to it — its specimen where the
general builders need paper data, its studies and figure scripts, its study evaluators and the
published numbers it registers into :mod:`bearingkit.validation` — on top of the general engine:

- :mod:`bearingkit.papers.tian2025` — Tian et al. (2025), ball–roller composite turntable bearing (seed 000);
- :mod:`bearingkit.papers.liu2022` — Liu et al. (2022), tapered roller bearing with roller scatter (seed 001);
- :mod:`bearingkit.papers.li2025` — Li et al. (2025), ball–column bearing with a flexible ring (seed 002);
- :mod:`bearingkit.papers.zheng2022` — Zheng et al. (2022), planetary thread roller bearing (seed 004).

The packages plug into the generic machinery through entry points (``bearingkit.validation`` for
their validation cases, ``bearingkit.evaluators`` for their study evaluators; see ``pyproject.toml``),
so nothing below this layer imports them. ``python -m bearingkit.papers OUT_DIR`` runs every paper's
example study.
"""
