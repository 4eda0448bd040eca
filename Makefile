# Two commands on a fresh machine: `make run` and `make test`. Both create .venv on first use.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
DOCS_STAMP := $(VENV)/.installed-docs
ROSS_STAMP := $(VENV)/.installed-ross
#: Test processes (pytest-xdist): one per core.
JOBS   ?= auto
# Python writes the byte code of what it imports (__pycache__, ignored by git): the installed packages are
# not byte-compiled by pip (--no-compile below), and with PYTHONDONTWRITEBYTECODE=1 (set on some
# machines and images) every process would compile bearingkit and its imports again (~0.8 s per CLI
# process measured, every test subprocess paying it).
unexport PYTHONDONTWRITEBYTECODE

.PHONY: run test test-slow bench lint validate docs compile wheel clean fuzz ross3

# One pip run installs everything `make run` and `make test` need: the package and its tests. The
# rotordynamics extra (ross-rotordynamics: plotly, scikit-learn, CoolProp, ...) comes with `make test-slow`,
# which runs the tests that load ROSS (marked `ross` and slow), and the docs site's packages with `make docs`: each a
# second pip run, so that `make test` installs 29 s instead of 48 s (warm cache, 2 cores, measured).
# --no-compile: pip byte-compiles every
# module it installs, ~70 of its ~120 s here (measured with a warm cache, 2 cores); Python compiles the
# modules a run imports on first use instead, a small part of them.
$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q --no-compile -e '.[dev]'
	touch $(STAMP)

$(ROSS_STAMP): $(STAMP)
	$(BIN)/python -m pip install -q --no-compile -e '.[dev,ross]'
	touch $(ROSS_STAMP)

$(DOCS_STAMP): $(STAMP)
	$(BIN)/python -m pip install -q --no-compile -e '.[dev,docs]'
	touch $(DOCS_STAMP)

# The compiled solver core, once per installed copy and version (about a minute; then cached).
compile: $(STAMP)
	$(BIN)/bearingkit compile

run: compile
	$(BIN)/bearingkit run-flagship

# ruff; the compiled core built once before the parallel tests (their processes then load it); the tests
# on every core, except the cases marked slow (make test-slow; .ci/run runs
# both); every published number; 300 fuzz mutants.
test: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/bearingkit compile
	bash scripts/ensure_chromium.sh
	$(BIN)/python -m pytest -n $(JOBS) --dist loadgroup -m "not slow"
	$(BIN)/bearingkit validate
	$(BIN)/python tests/fuzz/bk_fuzz_run.py --n $(CI_FUZZ_N)

# The mutation fuzz (tests/fuzz/bk_fuzz_run.py): N mutants of every command and input kind. SEED defaults
# to today's date, so CI's 300 mutants change every day; the seed is printed first, and any mutant runs
# again alone with --only INDEX.
SEED ?= $(shell date +%Y%m%d)
N ?= 10000
CI_FUZZ_N ?= 300
fuzz: compile
	$(BIN)/python tests/fuzz/bk_fuzz_run.py --seed $(SEED) --n $(N)

# ROSS 3 needs Python >= 3.12, CI's venv has 3.11 (ROSS 2.3): this runs the ROSS tests (marked `ross`) on
# ROSS 3 in their own venv, by hand (not in `make test`: a second install of the stack). PY312 names a
# Python 3.12+ (e.g. PY312=~/.pyenv/versions/3.12.1/bin/python); the numpy core spares a second compile.
PY312 ?= python3.12
ross3:
	@command -v $(PY312) >/dev/null || { echo "make ross3: no $(PY312) (set PY312 to a Python >= 3.12)"; exit 2; }
	test -x .venv-ross3/bin/python || $(PY312) -m venv .venv-ross3
	.venv-ross3/bin/python -m pip install -q --no-compile -e '.[dev,ross]'
	.venv-ross3/bin/python -c "import ross, sys; print('ROSS', ross.__version__, 'on Python', sys.version.split()[0])"
	BEARINGKIT_BACKEND=numpy .venv-ross3/bin/python -m pytest -p no:cacheprovider -m ross tests/systems

# The cases marked slow: larger repeats of what `make test` checks, process kills, every workbench page in
# Chromium, the ROSS rotors (each marker's comment says why it is slow and what stays fast).
test-slow: $(ROSS_STAMP)
	$(BIN)/bearingkit compile
	bash scripts/ensure_chromium.sh
	$(BIN)/python -m pytest -n $(JOBS) --dist loadgroup -m slow

# The sdist and the wheel built, the wheel installed without extras in a fresh venv and used from outside
# the tree (scripts/check_wheel.py; .ci/run runs it after the tests).
wheel: $(STAMP)
	$(BIN)/python scripts/check_wheel.py

# The documentation site (out/site): user guide, API reference, the example gallery run now.
docs: $(DOCS_STAMP)
	NO_MKDOCS_2_WARNING=1 $(BIN)/python -m mkdocs build --strict
	$(BIN)/python scripts/check_site.py out/site

# the compiled core built first: without it the first lines would time the numpy core while the
# compiled one builds in the background (a bench right after a fresh clone or a source change)
bench: compile
	$(BIN)/python -m benchmarks

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check . || true

validate: $(STAMP)
	$(BIN)/bearingkit validate

clean:
	rm -rf $(VENV) .venv-ross3 out .pytest_cache
