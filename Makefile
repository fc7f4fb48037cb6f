# The README's two commands: `make demo` and `make test`. Both set everything up first.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin

.PHONY: setup system demo test lint bench

system:
	bash scripts/install-system.sh

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q -e '.[dev]'
	touch $@

setup: system $(VENV)/.installed

demo: setup
	$(BIN)/eigendance demo

lint: setup
	$(BIN)/ruff check src tests benchmarks

test: lint
	$(BIN)/pytest -q

bench: setup
	$(BIN)/python benchmarks/run_all.py
