"""``[structure]`` of an input file → a :class:`~bearingkit.analysis.structure.Structure` (SI).

Each ring of :class:`~bearingkit.io.optional_sections.structure.StructureSpec` becomes a
:class:`~bearingkit.rings.curved_beam.FlexibleRing`: its section from the shape named (defaults from the
bearing: an outer ring from its raceway, pitch + D, to ``[geometry] outer_diameter``; an inner ring from
``[geometry] bore`` to pitch − D; a groove's bottom on the raceway and its radius the row's conformity
× D), its material from ``[material]``, its seat from ``seat_stiffness`` or a wall thickness (thin wall,
:func:`~bearingkit.physics.structure.thin_ring.housing_wall_stiffness`), its flange and split housing.
``[structure.imported]`` reads a Matrix Market or CSV matrix and a CSV of node coordinates (paths
relative to the input file and confined to its folder, :func:`bearingkit.io.reading.confined_path`;
regular files of at most :data:`MAX_MATRIX_BYTES`) into an
:class:`~bearingkit.rings.imported.ImportedStructure`, whose checks refuse a bad matrix in one line.
"""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from bearingkit import units
from bearingkit.errors import InputError

#: Largest matrix or node file read [bytes]: 64 MiB (a dense 1,200-DOF CSV matrix is ~30 MB).
MAX_MATRIX_BYTES = 64 << 20
#: Most DOFs of an imported matrix (its dense inverse is formed): 6 DOFs × 2,000 elements.
MAX_MATRIX_SIZE = 12_000

__all__ = ["MAX_MATRIX_BYTES", "structure_of"]


def structure_of(source: str, spec, model, geometry: dict, material):
    """The Structure of a validated ``[structure]`` (None when absent); InputError naming the field."""
    if spec is None:
        return None
    from bearingkit.analysis.structure import Structure

    parts = {}
    for side in ("outer", "inner"):
        ring = getattr(spec, side)
        if ring is not None:
            parts[side] = _prefixed(f"structure.{side}", _ring, ring, side, model, geometry, material)
    if spec.imported is not None:
        imp = spec.imported
        parts[imp.ring or "outer"] = _prefixed("structure.imported", _imported, imp, source, model)
    return Structure(outer=parts.get("outer"), inner=parts.get("inner"))


def _prefixed(prefix, fn, *args):
    try:
        return fn(*args)
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith("structure") else f"{prefix}: {text}") from None


def _rows(model, names):
    rows = list(model.rows)
    if names is None:
        return rows
    known = [r.name for r in rows]
    unknown = [n for n in names if n not in known]
    if unknown:
        raise InputError(f"rows ({unknown}) are not in the bearing; rows are {known}")
    return [r for r in rows if r.name in names]


def _raceway(rows, side):
    """(diameter of the raceway, element diameter, conformity, axial positions) of the rows a ring carries."""
    pitch = np.array([float(np.max(getattr(r, "pitch_diameter", np.nan))) for r in rows])
    dw = np.array([float(np.max(getattr(r, "element_diameter", np.nan))) for r in rows])
    if not np.all(np.isfinite(pitch)) or not np.all(np.isfinite(dw)):
        raise InputError("the rows give no pitch or element diameter: give inner_diameter and outer_diameter")
    z = np.array([float(np.max(getattr(r, "axial_position", 0.0))) for r in rows])
    sign = 1.0 if side == "outer" else -1.0
    raceway = pitch + sign * dw
    race = raceway.max() if side == "outer" else raceway.min()
    attr = "conformity_outer" if side == "outer" else "conformity_inner"
    conf = [getattr(r, attr, None) for r in rows]
    f = float(np.max(conf[0])) if conf and conf[0] is not None else None
    return race, float(dw.max()), f, z


def _ring(spec, side, model, geometry, material):
    from bearingkit.physics.structure.thin_ring import housing_wall_stiffness
    from bearingkit.rings import sections as S
    from bearingkit.rings.curved_beam import BoltedFlange, FlexibleRing, Foundation, SplitHousing

    rows = _rows(model, spec.rows)
    shape = spec.section or "rectangular"
    e = spec.youngs_modulus or material.youngs_modulus
    nu = spec.poisson_ratio if spec.poisson_ratio is not None else material.poisson_ratio
    mid = spec.axial_position or 0.0
    if shape == "given":
        r_c = spec.centroid_diameter / 2
        section = S.CurvedSection(
            spec.area, r_c, mid, spec.inertia_in, spec.inertia_out, spec.torsion_constant
        )
        width = spec.width or np.sqrt(12 * spec.inertia_out / spec.area)
        r_in = r_out = r_c
    else:
        depth = spec.groove_depth if shape == "grooved" else 0.0
        need = shape == "grooved" or (spec.inner_diameter if side == "outer" else spec.outer_diameter) is None
        race, dw, conf, zs = _raceway(rows, side) if need else (None, None, None, None)
        if side == "outer":
            r_in = spec.inner_diameter / 2 if spec.inner_diameter else race / 2 - depth
            od = spec.outer_diameter or geometry.get("outer_diameter")
            if od is None:
                raise InputError("outer_diameter (missing): give it here or in [geometry]")
            r_out = od / 2
        else:
            bore = spec.inner_diameter or geometry.get("bore")
            if bore is None:
                raise InputError("inner_diameter (missing): give it here or [geometry] bore")
            r_in = bore / 2
            r_out = spec.outer_diameter / 2 if spec.outer_diameter else race / 2 + depth
        if shape == "stepped":
            steps = [[units.parse(v, "length", f"steps[{i}]") for v in s] for i, s in enumerate(spec.steps)]
            parts = [S.rectangle(a / 2, b / 2, c, d) for a, b, c, d in steps]
            width = max(s[3] for s in steps) - min(s[2] for s in steps)
            r_in, r_out = min(s[0] for s in steps) / 2, max(s[1] for s in steps) / 2
        else:
            width = spec.width
            if not r_out > r_in:
                raise InputError(
                    f"the ring's section ({2 * r_in * 1e3:.6g} … {2 * r_out * 1e3:.6g} mm) has no wall: "
                    "check inner_diameter and outer_diameter"
                )
            box = (r_in, r_out, mid - width / 2, mid + width / 2)
            if shape == "grooved":
                if len(set(np.round(zs, 9))) > 1:
                    raise InputError(
                        "section ('grooved') models one raceway: the ring carries rows at several "
                        "axial positions; give a stepped or given section"
                    )
                radius = spec.groove_radius or (conf * dw if conf is not None else None)
                if radius is None:
                    raise InputError("groove_radius (missing): the rows give no conformity")
                face = "inner" if side == "outer" else "outer"
                parts = S.groove(*box, *_groove_centre(box, face, depth, radius, zs[0]), radius, face)
            else:
                parts = [S.rectangle(*box)]
        weights = None
        if spec.bolt_holes is not None:
            parts, weights = S.smear_bolt_holes(
                parts, spec.bolt_holes, spec.bolt_hole_diameter, spec.bolt_hole_circle / 2
            )
        torsion = None
        if shape == "rectangular" and weights is None:
            torsion = S.rectangular_torsion(r_out - r_in, width)
        section = S.section_of(parts, weights, torsion)
    foundation = Foundation(tangential=spec.tangential_support or 0.0, axial=spec.axial_support or 0.0)
    seat = spec.seat_stiffness
    if spec.seat_wall_thickness is not None:
        t = spec.seat_wall_thickness
        radius = r_out + t / 2 if side == "outer" else r_in - t / 2
        if not radius > 0:
            raise InputError(f"seat_wall_thickness ({t * 1e3:.6g} mm) is thicker than the shaft's radius")
        seat = float(housing_wall_stiffness(spec.seat_youngs_modulus or 2.08e11, t, radius, width))
    if seat:
        foundation = foundation + Foundation.seat(seat, width, mid - section.centroid_z)
    flange = None
    if spec.flange is not None:
        fl = spec.flange
        lateral = fl.lateral_stiffness or 0.0
        z_face = section.centroid_z + (1 if fl.face == "upper" else -1) * width / 2
        if spec.section != "given":
            z_face = mid + (1 if fl.face == "upper" else -1) * width / 2
        flange = BoltedFlange(
            fl.n_bolts, fl.bolt_circle_diameter / 2, fl.bolt_stiffness, lateral, lateral, z_face,
            fl.phase or 0.0, fl.face_stiffness or 0.0, fl.face_width or 0.0,
        )  # fmt: skip
    split = None
    if spec.split is not None:
        sp = spec.split
        split = SplitHousing(
            np.pi / 2 if sp.azimuth is None else sp.azimuth,
            np.radians(10.0) if sp.gap is None else sp.gap,
            sp.remaining or 0.0,
        )
    kwargs = {}
    if spec.harmonics is not None:
        kwargs["harmonics"] = spec.harmonics
    return FlexibleRing(
        section, e, nu, side, foundation, flange, split,
        stiffness_scale=spec.stiffness_scale or 1.0,
        rows=None if spec.rows is None else tuple(spec.rows),
        **kwargs,
    )  # fmt: skip


def _groove_centre(box, face, depth, radius, z):
    """(centre r, centre z) of a groove of ``radius`` whose bottom lies ``depth`` beyond the ``face``."""
    r_in, r_out = box[0], box[1]
    if face == "inner":
        return r_in + depth - radius, z
    return r_out - depth + radius, z


# -- imported matrices -------------------------------------------------------------------------------
def _path(source: str, name: str, field: str) -> Path:
    """The file ``name`` that ``[structure.imported]`` gives as ``field``, confined as every path a data
    file names (:func:`bearingkit.io.reading.confined_path`, docs/security.md): relative to the input
    file's folder and inside it (or its project's folder above it); no ``~``, no hidden names, an absolute
    path only there too. Nothing is opened here."""
    from bearingkit.io.reading import confined_path

    base = Path(source).parent if source and not source.startswith("<") else Path.cwd()
    try:
        return confined_path(name, base, f"structure.imported.{field}")
    except InputError as exc:  # analyze has no --allow-path: say where the file must be instead
        text = str(exc)
        if " lies outside " in text:
            text = text.split(" lies outside ")[0] + (
                " lies outside this file's folder (and its project's folder above it): put the FE "
                "export beside the input file or below it"
            )
        raise InputError(text) from None


def _read_matrix(path: Path) -> np.ndarray:
    from bearingkit.io.reading import read_text

    text = read_text(path, limit=MAX_MATRIX_BYTES)
    if path.suffix.lower() == ".mtx":
        import scipy.io

        try:
            m = scipy.io.mmread(io.StringIO(text))
        except (ValueError, IndexError, TypeError) as exc:
            raise InputError(f"{path}: not a Matrix Market file ({str(exc).splitlines()[0][:80]})") from None
        m = m.toarray() if hasattr(m, "toarray") else np.asarray(m)
        return np.asarray(m, dtype=float)
    return _csv(path, text)


def _csv(path: Path, text: str) -> np.ndarray:
    rows = []
    for n, line in enumerate(text.splitlines(), start=1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        cells = [c.strip() for c in line.replace(";", ",").split(",")]
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            if rows:  # a header is allowed before the numbers only
                raise InputError(f"{path}: line {n} is not numbers separated by commas") from None
            continue
    if not rows:
        raise InputError(f"{path}: holds no numbers")
    widths = {len(r) for r in rows}
    if len(widths) != 1:
        raise InputError(f"{path}: its lines hold different numbers of values ({sorted(widths)})")
    return np.array(rows, dtype=float)


def _imported(spec, source, model):
    from bearingkit.rings.imported import ImportedStructure

    matrix_path, nodes_path = _path(source, spec.matrix, "matrix"), _path(source, spec.nodes, "nodes")
    matrix = _read_matrix(matrix_path)
    if matrix.shape[0] > MAX_MATRIX_SIZE:
        raise InputError(f"matrix ({matrix.shape[0]} DOFs) must have at most {MAX_MATRIX_SIZE}")
    nodes = (
        _read_matrix(nodes_path)
        if spec.nodes.lower().endswith(".mtx")
        else _csv(nodes_path, _read_nodes(nodes_path))
    )
    if nodes.ndim != 2 or nodes.shape[1] != 3:
        raise InputError(f"nodes ({spec.nodes}) must hold three coordinates x, y, z per line")
    if spec.length_unit:
        nodes = nodes * units.parse(f"1 {spec.length_unit}", "length", "length_unit")
    kind = spec.kind or "stiffness"
    dofs = tuple(spec.dofs or ("ux", "uy", "uz"))
    if spec.matrix_unit:
        if any(d.startswith("r") for d in dofs):
            raise InputError(
                "matrix_unit applies to translational DOFs only: give a matrix with rotations in SI"
            )
        dim = "stiffness" if kind == "stiffness" else "length"
        text = f"1 {spec.matrix_unit}" if kind == "stiffness" else f"1 {spec.matrix_unit}*N"
        matrix = matrix * units.parse(text, dim, "matrix_unit")
    _rows(model, spec.rows)
    return ImportedStructure(
        matrix,
        nodes,
        dofs,
        kind,
        spec.ring or "outer",
        None if spec.rows is None else tuple(spec.rows),
        bool(spec.free),
        spec.stiffness_scale or 1.0,
        f"structure.imported ({spec.matrix})",
    )


def _read_nodes(path: Path) -> str:
    from bearingkit.io.reading import read_text

    return read_text(path, limit=MAX_MATRIX_BYTES)
