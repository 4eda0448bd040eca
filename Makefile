# Two commands on a fresh machine: `make run` and `make test`. Both create .venv on first use.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: run test test-slow bench lint validate clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	@echo "installing bearingkit with the [dev] and [ross] extras: the ROSS export test (tests/systems/test_ross_export.py) must run in CI"
	$(BIN)/python -m pip install -q -e '.[dev,ross]'
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/bearingkit run-flagship

test: $(STAMP)
	$(BIN)/ruff check .
	bash scripts/ensure_chromium.sh
	$(BIN)/python -m pytest
	$(BIN)/python -m pytest -m ross tests/systems
	$(BIN)/bearingkit validate

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
