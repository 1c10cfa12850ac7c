# `make demo` and `make test` set everything up themselves on a fresh machine.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV ?= .venv
BIN := $(VENV)/bin
OUT ?= out/demo

.PHONY: demo test test-long test-fast lint bench fuzz clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# Stamps re-run the install when pyproject.toml changes.
$(VENV)/.installed: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e .
	touch $@

# The tests also exercise the optional simulators, Ray and the robot stack, so the dev set-up installs those extras.
$(VENV)/.installed-dev: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[dev,bullet,usd,ray,robot,policy,view]'
	$(BIN)/python -m pip install --quiet --no-deps robomimic==0.3.0
	touch $@ $(VENV)/.installed

demo: $(VENV)/.installed
	$(BIN)/physcensis generate "a dining table set up for four people" --support table:1.2x0.8 --out $(OUT)

# The suite runs on TEST_WORKERS processes (pytest-xdist; worksteal balances the long physics tests). `make test`
# leaves out the end-to-end runs marked long (five seconds or more each: the prompt suites, real multi-process
# batches, command-line runs, the demo, whole-catalogue physics, the README's code, the fragility search), which
# `make test-long` runs; CI runs both.
TEST_WORKERS ?= 2
test: $(VENV)/.installed-dev
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS) --dist worksteal -m "not long"

test-long: $(VENV)/.installed-dev
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS) --dist worksteal -m long

# The suite without the tests marked slow (each several seconds or more) or long: a quick check while working.
test-fast: $(VENV)/.installed-dev
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS) --dist worksteal -m "not slow and not long"

# The fuzz harness (tests/fuzz) with its long profile: FUZZ_EXAMPLES random examples per target, failures shrunk and
# kept in .hypothesis/ (`make test` runs the same targets briefly, derandomized). Under a virtual-memory cap of
# FUZZ_MEMORY_KB, so that a reader allocating without bound fails (MemoryError) instead of exhausting the machine.
FUZZ_EXAMPLES ?= 3000
FUZZ_MEMORY_KB ?= 8000000
fuzz: $(VENV)/.installed-dev
	ulimit -v $(FUZZ_MEMORY_KB) && FUZZ_PROFILE=long FUZZ_EXAMPLES=$(FUZZ_EXAMPLES) \
		$(BIN)/python -m pytest -q -m fuzz tests/fuzz

# ruff (lint and format) over the package and the tests, mypy over the package; CI runs it before the tests.
lint: $(VENV)/.installed-dev
	$(BIN)/ruff check src tests
	$(BIN)/ruff format --check src tests
	$(BIN)/mypy src

bench: $(VENV)/.installed-dev
	$(BIN)/python -m physcensis.bench --out bench/results

clean:
	rm -rf $(VENV) out .pytest_cache .hypothesis
