"""A study file is checked whole before anything is written (issue 24, items 3 and the bad-file rule).

- the study ``name`` becomes a folder name: traversal, separators, absolute paths are refused;
- every malformed value gives one line naming the file and the field (exit 2 from the CLI), never a
  traceback: the file may come from someone else (hypothesis mutates valid files at random);
- sizes that would exhaust memory before the first case runs (factorial explosions, huge Monte
  Carlo draws, NSGA-III reference directions) are refused in one line;
- a refused study leaves no output folder (the audit found an empty ``--out`` folder left behind).
"""

import copy
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.studies.__main__ import main
from bearingkit.studies.definition import load as sd

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

VALID = {
    "factorial": {
        "study": {"name": "grid", "design": "factorial", "evaluator": "seed000_statics", "chunk_size": 4},
        "fixed": {"axial_load": "3 kN"},
        "factors": [
            {"name": "clearance_axial_ball", "levels": ["-3 um", "-5 um"]},
            {"name": "crowning", "levels": ["a", "e"]},
        ],
    },
    "levels_x_samples": {
        "study": {"name": "lxs", "design": "orthogonal", "array": "L9", "evaluator": "seed000_statics"},
        "factors": [
            {"name": "axial_load", "levels": ["1 kN", "2 kN", "3 kN"]},
            {"name": "eccentricity", "levels": ["0 m", "0.1 m", "0.2 m"]},
        ],
        "monte_carlo": {
            "per_point": 3,
            "factors": [{"name": "radial_load", "distribution": "normal", "mean": "1 kN", "std": "0.1 kN"}],
        },
    },
    "optimize": {
        "study": {"name": "z", "design": "optimize", "evaluator": "zdt1"},
        "variables": [{"name": "x1", "low": 0, "high": 1}, {"name": "x2", "low": 0, "high": 1}],
        "objectives": [{"output": "f1"}, {"output": "f2"}],
        "constraints": [{"output": "g", "upper": 2}],
        "optimizer": {"pop_size": 10, "generations": 2},
        "targets": {"t": {"x1": 0.5}},
    },
}


@pytest.mark.parametrize(
    "name",
    ["x/../../../../victim", "../up", "/etc/x", "a/b", "a\\b", ".hidden", "..", "", "x" * 65, "nul\x00"],
)
def test_unsafe_names_are_refused(name):
    data = copy.deepcopy(VALID["factorial"])
    data["study"]["name"] = name
    with pytest.raises(InputError, match=r"^f\.toml: study\.name \(.*\) must be a plain name"):
        sd.from_dict(data, source="f.toml")


def test_plain_names_pass():
    for name in ("seed000_l9", "run-2.b", "A1"):
        data = copy.deepcopy(VALID["factorial"])
        data["study"]["name"] = name
        assert sd.from_dict(data).name == name


def test_traversal_name_writes_nothing_outside(tmp_path, monkeypatch, capsys):
    """The audit's reproducer: the name became a path and results.csv landed outside."""
    work = tmp_path / "a" / "b"
    work.mkdir(parents=True)
    (work / "study.toml").write_text(
        '[study]\nname = "x/../../victim"\ndesign = "factorial"\nevaluator = "zdt1"\n'
        '[[factors]]\nname = "x1"\nlevels = [0, 1]\n'
    )
    monkeypatch.chdir(work)
    assert main(["study.toml", "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "study.name ('x/../../victim')" in err
    assert sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*")) == [
        "a",
        "a/b",
        "a/b/study.toml",
    ]


@pytest.mark.parametrize(
    ("patch", "field"),
    [
        (
            {"factors": [{"name": f"x{i}", "levels": list(range(10))} for i in range(1, 11)]},
            "10,000,000,000 cases",
        ),
        ({"study": {"design": "monte_carlo", "samples": 10**12}}, "at most 10,000,000"),
        ({"optimizer": {"pop_size": 10**6, "generations": 10**6}}, "evaluations"),
        ({"optimizer": {"algorithm": "nsga3", "n_partitions": 10**6}}, "optimizer.n_partitions"),
        ({"study": {"seed": -1}}, "study.seed"),
        ({"study": {"chunk_size": 10**9}}, "study.chunk_size"),
        ({"study": {"design": "orthogonal", "array": "L99"}}, "study.array ('L99')"),
    ],
)
def test_sizes_that_would_exhaust_memory_are_refused(patch, field):
    base = (
        VALID["optimize"]
        if "optimizer" in patch
        else {
            "study": {"name": "big", "design": "factorial", "evaluator": "zdt1"},
            "factors": [{"name": "x1", "levels": [0.0, 1.0]}],
        }
    )
    data = copy.deepcopy(base)
    for key, value in patch.items():
        data[key] = {**data.get(key, {}), **value} if isinstance(value, dict) else value
    if data["study"].get("design") == "monte_carlo":
        data["factors"] = [{"name": "x1", "distribution": "uniform", "low": 0, "high": 1}]
    with pytest.raises(InputError, match=field.replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")):
        sd.from_dict(data)


# ----------------------------------------------------------------------------- random bad files
VALUES = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(10**12), max_value=10**12),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
    st.sampled_from(["3 kN", "-2 um", "../x", "L4", "nsga3", "1e400 N", "x:y", "normal"]),
    st.lists(st.integers(0, 3), max_size=3),
    st.dictionaries(st.sampled_from(["name", "levels", "a"]), st.integers(0, 2), max_size=2),
    st.builds(lambda: [{}]),
)


def _paths(node, prefix=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield (*prefix, k)
            yield from _paths(v, (*prefix, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield (*prefix, i)
            yield from _paths(v, (*prefix, i))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    base=st.sampled_from(sorted(VALID)),
    edits=st.lists(st.tuples(st.integers(0, 10**6), st.booleans(), VALUES), min_size=1, max_size=3),
)
def test_any_malformed_file_gives_one_line_or_loads(base, edits):
    data = copy.deepcopy(VALID[base])
    for pick, delete, value in edits:
        paths = list(_paths(data))
        if not paths:
            break
        path = paths[pick % len(paths)]
        parent = data
        for key in path[:-1]:
            parent = parent[key]
        if delete:
            del parent[path[-1]]
        else:
            parent[path[-1]] = copy.deepcopy(value)
    try:
        d = sd.from_dict(data, source="f.toml")
    except InputError as exc:
        msg = str(exc)
        assert "\n" not in msg and msg.startswith("f.toml: ") and len(msg) < 400, msg
    else:  # a file that loads is a study that can be planned (cases, bearing, evaluator)
        assert sd.case_count(d) <= sd.MAX_CASES
        from bearingkit.studies.run.cases import plan_study

        try:
            plan = plan_study(d)
        except InputError as exc:
            assert "\n" not in str(exc) and str(exc).startswith("f.toml: "), str(exc)
        else:
            assert plan.cases is None or len(plan.cases) == sd.case_count(d)


# ---------------------------------------------------------------------------------- the CLI rule
@pytest.mark.parametrize(
    ("text", "field"),
    [
        (
            '[study]\nname = "a"\ndesign = "factorial"\nevaluator = "zdt1"\nchunk_size = "x"\n',
            "study.chunk_size",
        ),
        (
            '[study]\nname = "a"\ndesign = "factorial"\nevaluator = "zdt1"\n'
            '[[factors]]\nname = "x1"\nlevels = 5\n',
            "factors[0] (x1).levels",
        ),
        ('[study]\nname = "a"\ndesign = "sweep"\nevaluator = "zdt1"\nfactors = 3\n', "study.factors"),
        ('name = "a"\ndesign = "sweep"\nevaluator = "zdt1"\n', "[study] table"),
        ('[study]\nname = "a"\ndesign = "optimize"\nevaluator = "zdt1"\n[targets]\nt = 1\n', "targets.t"),
        ('[study]\nname = "a"\ndesign = "grid"\nevaluator = "zdt1"\n', "study.design ('grid')"),
        ("not toml [", "not valid TOML"),
    ],
)
def test_bad_files_exit_2_with_one_line_naming_the_field(tmp_path, capsys, text, field):
    f = tmp_path / "s.toml"
    f.write_text(text)
    out = tmp_path / "out"
    assert main([str(f), "--out", str(out), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ") and field in err, err
    assert not out.exists()


def test_a_study_refused_at_run_time_leaves_no_folder(tmp_path, capsys):
    """The bearing file is of another type: found when the cases are built, still before any write."""
    f = tmp_path / "s.toml"
    f.write_text(
        '[study]\nname = "wrong_bearing"\ndesign = "factorial"\nevaluator = "seed000_statics"\n'
        f'bearing = "{(EXAMPLES / "trb_32008.toml").as_posix()}"\n'
        '[[factors]]\nname = "axial_load"\nlevels = ["1 kN"]\n'
    )
    out = tmp_path / "out"
    assert main([str(f), "--out", str(out), "--no-progress", "--allow-path", str(EXAMPLES)]) == 2
    err = capsys.readouterr().err
    assert "study.bearing" in err and "composite_turntable" in err
    assert not out.exists(), "a refused study leaves no output folder"
