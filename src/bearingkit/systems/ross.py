"""Export to ROSS (ross-rotordynamics): bearing elements from stiffness tables, and whole rotors.

SI units (ROSS takes SI floats). Optional dependency: ``pip install 'bearingkit[ross]'``.

A ROSS ``BearingElement`` takes kxx, kxy, kyx, kyy (and kzz) as constants or as tables over the rotor
speed [rad/s], which ROSS interpolates when it evaluates the bearing at a rotor speed. ROSS 2 calls that
axis ``frequency=``; ROSS 3 (petrobras/ross PR #1371, ROSS 3.0) calls it ``speed=`` and gives
``frequency=`` another meaning, the excitation (whirl) frequency: a rotor-speed table passed as
``frequency=`` to ROSS 3 would be read along the wrong axis, silently (a Campbell diagram or a modal
analysis at speed would interpolate the stiffness at the whirl frequency instead of the rotor speed).
:func:`speed_axis` reads which keyword the installed ROSS's ``BearingElement`` declares (ROSS 2.x
accepts any keyword through ``**kwargs``, so only a declared ``speed`` parameter counts) and
:func:`ross_bearing` passes the table along that axis. :func:`ross_bearing` passes a
:class:`~bearingkit.systems.shaft.stiffness.StiffnessTable`'s radial block and axial term: one point →
constants, several points at distinct speeds → a speed-indexed element. The element has no
tilt stiffness and no force–tilt coupling (ROSS's bearing element acts on x, y, z only): those terms
stay in the JSON/CSV table. Damping is not computed by bearingkit: the element gets ``damping``
(default 0) in cxx = cyy.

:func:`ross_rotor` builds the whole rotor from a solved shaft: one ROSS ``ShaftElement`` per
bearingkit element (same lengths, diameters, material, Timoshenko shear on or off), a
``BearingElement`` at each seat node with that bearing's stiffness at the chosen load cases, and a
``DiskElement`` for each gear with a mass, taken as a solid disc of its pitch diameter
(I_p = m d²/8, I_d = I_p/2 — an assumption: bearingkit does not know the gear's real inertia), and one
without inertia for each point mass.
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
import warnings

import numpy as np

from bearingkit.errors import InputError
from bearingkit.extras import MissingExtra
from bearingkit.systems.shaft.stiffness import StiffnessTable, shaft_stiffness_table

#: What to install when ROSS is missing.
INSTALL_HINT = "pip install 'bearingkit[ross]'"


def import_ross():
    """The ``ross`` module (ross-rotordynamics), imported quietly; InputError when not installed.

    ROSS imports ccp, which prints a REFPROP notice (from Python and from its C++ fluid library, on
    both streams) when that proprietary library is absent; it is irrelevant here and would corrupt
    ``--json`` output, so the import runs with file descriptors 1 and 2 sent to the null device.
    """
    from bearingkit.extras import check, message

    check("ross", "the ROSS export (bearingkit.systems.ross)")
    try:
        with _quiet():
            import ross
    except ImportError as exc:  # installed but broken (e.g. ROSS 2 with plotly >= 6)
        raise MissingExtra(message("ross", "the ROSS export", [f"a working ross ({exc})"])) from None
    return ross


@contextlib.contextmanager
def _quiet():
    """Discard what Python and native code write to stdout and stderr inside the block."""
    saved = []
    sys.stdout.flush()
    sys.stderr.flush()
    with open(os.devnull, "w") as null, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            for fd in (1, 2):
                saved.append((fd, os.dup(fd)))
                os.dup2(null.fileno(), fd)
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                yield
        finally:
            for fd, copy in saved:
                os.dup2(copy, fd)
                os.close(copy)


def speed_axis(rs=None) -> str:
    """The ``BearingElement`` keyword of a rotor-speed table in the installed ROSS: ``"speed"`` (ROSS 3,
    declared parameter) or ``"frequency"`` (ROSS 2, where ``frequency=`` is the rotor speed)."""
    import inspect

    rs = rs or import_ross()
    params = inspect.signature(rs.BearingElement.__init__).parameters
    declared = params.get("speed")
    return (
        "speed"
        if declared is not None and declared.kind is not inspect.Parameter.VAR_KEYWORD
        else "frequency"
    )


def ross_bearing(table: StiffnessTable, node: int, *, damping: float = 0.0, tag: str | None = None):
    """A ROSS ``BearingElement`` at ``node`` from the radial block and axial term of ``table``.

    Parameters
    ----------
    table : StiffnessTable
        One point (constant coefficients) or points at distinct speeds (a rotor-speed table,
        interpolated by ROSS; points are sorted by speed; ``speed=`` in ROSS 3, ``frequency=`` in ROSS 2).
        Use ``table.select`` to pick one load level.
    node : int
        ROSS node index.
    damping : float [N·s/m]
        cxx = cyy (bearingkit computes no damping).
    tag : str, optional
        Element tag (default the bearing name).

    Returns
    -------
    ross.BearingElement
    """
    rs = import_ross()
    if not np.all(table.converged):
        bad = table.labels[int(np.flatnonzero(~table.converged)[0])]
        raise InputError(f"stiffness table point {bad!r} did not converge; no ROSS element from it")
    order = np.argsort(table.speeds, kind="stable")
    k = table.stiffness[order]
    speeds = table.speeds[order]
    coeff = {
        "kxx": k[:, 0, 0],
        "kxy": k[:, 0, 1],
        "kyx": k[:, 1, 0],
        "kyy": k[:, 1, 1],
        "kzz": k[:, 2, 2],
    }
    tag = tag or table.bearing
    if len(table) == 1:
        return rs.BearingElement(n=node, cxx=damping, tag=tag, **{n: float(v[0]) for n, v in coeff.items()})
    if len(np.unique(speeds)) != len(speeds):
        raise InputError(
            f"stiffness table of {table.bearing!r} has {len(speeds)} points but repeated speeds; ROSS "
            "interpolates over speed only: select one point per speed (StiffnessTable.select)"
        )
    return rs.BearingElement(
        n=node,
        cxx=np.full(len(speeds), damping),
        tag=tag,
        **{speed_axis(rs): speeds},  # the rotor-speed axis of this ROSS (module docstring)
        **{n: np.asarray(v, dtype=float) for n, v in coeff.items()},
    )


def ross_material(material):
    """ROSS material of a :class:`bearingkit.materials.Material` (E, ν, ρ)."""
    rs = import_ross()
    return rs.Material(
        name=material.name.replace(" ", "_"),
        rho=material.density,
        E=material.youngs_modulus,
        Poisson=material.poisson_ratio,
    )


def ross_rotor(result, cases=None, *, damping: float = 0.0):
    """A ROSS ``Rotor`` of a solved shaft with its bearings' stiffness at the load cases ``cases``.

    Parameters
    ----------
    result : ShaftResult
    cases : sequence of int, optional
        Load cases whose stiffness the bearing elements carry: one case → constant coefficients;
        several (at distinct speeds) → speed-indexed elements. Default: every case.
    damping : float [N·s/m]
        Bearing damping cxx = cyy.

    Returns
    -------
    ross.Rotor
    """
    rs = import_ross()
    system = result.system
    mesh = result.assembly.mesh
    cases = np.arange(result.n_cases) if cases is None else np.asarray(cases, dtype=int)
    bearings = [
        (int(node), shaft_stiffness_table(result, b.name).select(cases), b.name)
        for b, node in zip(system.bearings, result.assembly.seat_nodes, strict=True)
    ]
    gears = [(g.name, g.position, g.mass, g.pitch_diameter) for g in system.gears]
    # ROSS's PointMass links bearing nodes; a lumped mass on the shaft is a disc without inertia.
    return _rotor(rs, system.shaft, mesh, bearings, gears, system.masses, damping)


def cases_by_speed(speeds) -> list[int]:
    """The first load case of each distinct rotor speed (in the order met): the cases a rotor's bearing
    elements carry, speed-indexed when there are several (ROSS interpolates over speed only).

    Parameters
    ----------
    speeds : array_like (C,) [rad/s]
        The rotor's speed per case (its magnitude counts; 0 without speeds).
    """
    out, seen = [], []
    for c, w in enumerate(np.abs(np.asarray(speeds, float))):
        if not any(np.isclose(w, s, rtol=1e-12, atol=1e-12) for s in seen):
            seen.append(w)
            out.append(c)
    return out


def _rotor(rs, shaft, mesh, bearings, gears, masses, damping):
    """A ROSS Rotor of one Shaft on its mesh: ShaftElements, BearingElements [(node, table, tag)], discs."""
    mat = ross_material(shaft.material)
    elements = [
        rs.ShaftElement(
            L=float(length),
            idl=float(di),
            odl=float(do),
            material=mat,
            n=i,
            shear_effects=shaft.shear_deformation,
            rotary_inertia=True,
            gyroscopic=True,
        )
        for i, (length, di, do) in enumerate(
            zip(mesh.length, mesh.inner_diameter, mesh.outer_diameter, strict=True)
        )
    ]
    # ROSS refuses two elements with one tag; a shaft file may repeat a name (two masses keep the default
    # name "mass"; the fuzz repeated a [[shaft.masses]] table 17 times): later ones get " #2", " #3" …
    tag = _unique_tags()
    elems = [ross_bearing(table, int(node), damping=damping, tag=tag(name)) for node, table, name in bearings]
    disks = []
    for name, position, mass, diameter in gears:
        if mass > 0:
            ip = mass * diameter**2 / 8.0
            disks.append(rs.DiskElement(n=mesh.node(position), m=mass, Id=ip / 2.0, Ip=ip, tag=tag(name)))
    disks += [
        rs.DiskElement(n=mesh.node(m.position), m=m.mass, Id=0.0, Ip=0.0, tag=tag(m.name)) for m in masses
    ]
    return rs.Rotor(elements, disks, elems)


def _unique_tags():
    """A function giving each name it is called with once as it is, then with " #2", " #3" … appended."""
    seen: dict[str, int] = {}

    def tag(name):
        name = str(name)
        seen[name] = seen.get(name, 0) + 1
        return name if seen[name] == 1 else f"{name} #{seen[name]}"

    return tag


def drivetrain_rotors(analysis, *, damping: float = 0.0) -> tuple[dict, list[str]]:
    """One ROSS ``Rotor`` per shaft (and planet) of a solved drivetrain, and notes on what each holds.

    Each rotor is its shaft's Timoshenko mesh (as :func:`ross_rotor`), a ``DiskElement`` per gear with a
    mass (solid disc of the reference diameter, the same assumption) and per point mass, and a
    ``BearingElement`` for every bearing with a ring on the shaft's axis, its other ring taken as ground
    (the housing; for a shaft-in-shaft bearing the other shaft, for a planet bearing the carrier's pin,
    held rigid). The stiffness is the bearing's tangent at the solved load cases — the first case of each
    distinct speed of the shaft, tabulated over the shaft's speed |ω| [rad/s] (speed-indexed elements
    when the cases run at several speeds, constants otherwise). Not in the rotors: the gear meshes'
    stiffness coupling the shafts, and the planet bearings on the carrier's pins (off its axis).

    Parameters
    ----------
    analysis : DrivetrainAnalysis
        Solved, every case converged.
    damping : float [N·s/m]
        Bearing damping cxx = cyy (bearingkit computes none).

    Returns
    -------
    (dict, list of str)
        Shaft name → ``ross.Rotor``; the notes (which cases each rotor's stiffness comes from).
    """
    import dataclasses

    from bearingkit.systems.drivetrain.output import stiffness_tables

    rs = import_ross()
    res, dt = analysis.result, analysis.drivetrain
    if not np.all(res.converged):
        raise InputError("ROSS rotors only from a drivetrain whose every load case converged")
    tables = {t.bearing: t for t in stiffness_tables(analysis)}
    omega = analysis.omega or {}
    rotors, notes, left_out = {}, [], []
    for s in dt.shafts:
        blk = res.assembly.blocks[s.name]
        speed = np.abs(np.asarray(omega.get(s.name, np.zeros(analysis.n_cases)), float))
        speed = np.broadcast_to(speed, (analysis.n_cases,))
        cases = cases_by_speed(speed)
        bearings = []
        for b in dt.bearings:
            for att in (b.inner, b.outer):
                if att.body != s.name:
                    continue
                if np.any(np.asarray(att.arm, float) != 0.0):
                    left_out.append(f"{b.name} (on {s.name}'s arm)")
                    continue
                table = dataclasses.replace(tables[b.name], speeds=np.array(speed)).select(cases)
                bearings.append((blk.mesh.node(att.position), table, b.name))
        gears = [(g.name, g.position, g.mass, g.geometry.reference_diameter) for g in s.gears]
        rotors[s.name] = _rotor(rs, s.shaft, blk.mesh, bearings, gears, s.masses, damping)
        used = ", ".join(analysis.case_names[c] for c in cases)
        notes.append(
            f"ROSS rotor {s.name!r}: {len(bearings)} bearing elements, stiffness of case(s) {used} "
            f"over the shaft's speed"
        )
    notes.append("ROSS rotors: the gear meshes' stiffness between the shafts is not in them")
    if left_out:
        notes.append("ROSS rotors: bearings off a shaft's axis left out: " + ", ".join(left_out))
    return rotors, notes


def shaft_rotors(result, *, damping: float = 0.0) -> tuple[dict, list[str]]:
    """The ROSS rotor of a solved shaft (``bearingkit shaft --ross``): :func:`ross_rotor` at the first load
    case of each distinct speed (speed-indexed bearing elements when there are several), and a note.

    Parameters
    ----------
    result : ShaftResult
        Every case converged.
    damping : float [N·s/m]

    Returns
    -------
    (dict, list of str)
        {shaft name: ``ross.Rotor``} and the notes.
    """
    if not np.all(result.converged):
        raise InputError("a ROSS rotor only from a shaft whose every load case converged")
    speeds = result.loads.speed if result.loads.speed is not None else np.zeros(result.n_cases)
    cases = cases_by_speed(np.broadcast_to(np.asarray(speeds, float), (result.n_cases,)))
    name = result.system.name
    used = ", ".join(result.loads.names[c] for c in cases)
    note = f"ROSS rotor {name!r}: {len(result.system.bearings)} bearing elements, stiffness of case(s) {used}"
    return {name: ross_rotor(result, cases, damping=damping)}, [note + " over the shaft's speed"]


def write_rotors(rotors: dict, folder) -> list:
    """Save ROSS rotors as ``folder/<name>.toml`` (``Rotor.save``; ``ross.Rotor.load`` reads them back).

    The folder is made if missing; returns the paths written."""
    from pathlib import Path

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for name, rotor in rotors.items():
        path = folder / f"{_file_stem(name)}.toml"
        with _quiet():
            rotor.save(path)
        out.append(path)
    return out


def _file_stem(name: str) -> str:
    """A shaft name as a file name: characters other than letters, digits, '-', '_' and '.' become '_'."""
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name) or "shaft"
