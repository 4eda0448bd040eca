# Two commands on a fresh machine: `make run` and `make test`. Both create .venv on first use.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
ROSS   := $(VENV)/.installed-ross

.PHONY: run test test-slow bench lint validate clean fuzz

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[dev]'
	touch $(STAMP)

# The tests also need the optional rotordynamics extra (ross-rotordynamics, ~2 min to install).
$(ROSS): $(STAMP)
	@echo "installing the [ross] extra: the ROSS export test (tests/systems/test_ross_export.py) must run in CI"
	$(BIN)/python -m pip install -q -e '.[dev,ross]'
	touch $(ROSS)

run: $(STAMP)
	$(BIN)/bearingkit run-flagship

test: $(ROSS)
	$(BIN)/ruff check .
	bash scripts/ensure_chromium.sh
	$(BIN)/python -m pytest
	$(BIN)/python -m pytest -m ross tests/systems
	$(BIN)/bearingkit validate
	$(BIN)/python tests/fuzz/bk_fuzz_run.py --n $(CI_FUZZ_N)

# The mutation fuzz (tests/fuzz/bk_fuzz_run.py): N mutants of every command and input kind. SEED defaults
# to today's date, so CI's 300 mutants change every day; the seed is printed first, and any mutant runs
# again alone with --only INDEX.
SEED ?= $(shell date +%Y%m%d)
N ?= 10000
CI_FUZZ_N ?= 300
fuzz: $(STAMP)
	$(BIN)/python tests/fuzz/bk_fuzz_run.py --seed $(SEED) --n $(N)

test-slow: $(STAMP)
	$(BIN)/python -m pytest -m slow

bench: $(STAMP)
	$(BIN)/python -m benchmarks

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check . || true

validate: $(STAMP)
	$(BIN)/bearingkit validate

clean:
	rm -rf $(VENV) out .pytest_cache
