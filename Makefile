# The README's two commands: `make demo` and `make test`. Both set everything up first.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin

.PHONY: setup system web demo test test-web lint bench blender

system:
	bash scripts/install-system.sh

# constraints.txt pins every package to the versions the tests last passed with (pyproject.toml
# keeps the ranges the library supports); refresh it with `pip freeze --exclude-editable`.
$(VENV)/.installed: pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q -c constraints.txt -e '.[dev,ray,link]'  # ray: the batch tests run on Ray too; link: the Link test
	$(BIN)/python -c 'from eigendance.music.spectrogram import warm_up; warm_up()'  # numba's JIT, once
	touch $@

# The front end (web/, TypeScript + three.js + Vite) is built into src/eigendance/static/.
web: system
	bash scripts/web.sh install
	bash scripts/web.sh build

setup: system web $(VENV)/.installed

# Blender as a Python module (the `blender` extra, bpy, about 1 GB) for the tests that open
# exports in Blender, in a virtual environment of its own (bpy pins its own numpy); installed once
# per machine by `make test`.
BLENDER_VENV := .venv-blender
# Blender 4.2 LTS as well (the wheel for Python 3.11 of the LTS still in wide use): the export
# tests check that both play the files, each in a virtual environment of its own.
BLENDER_LTS_VENV := .venv-blender42
BLENDER_LTS := bpy==4.2.0 numpy==1.26.4  # 4.2 was built against numpy 1.x: 2.x crashes foreach_get
blender: $(BLENDER_VENV)/.installed $(BLENDER_LTS_VENV)/.installed

$(BLENDER_VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(BLENDER_VENV)
	$(BLENDER_VENV)/bin/pip install -q $$($(PYTHON) -c 'import tomllib; print(*tomllib.load(open("pyproject.toml", "rb"))["project"]["optional-dependencies"]["blender"])')
	touch $@

$(BLENDER_LTS_VENV)/.installed:
	$(PYTHON) -m venv $(BLENDER_LTS_VENV)
	$(BLENDER_LTS_VENV)/bin/pip install -q $(BLENDER_LTS)
	touch $@

demo: setup
	$(BIN)/eigendance demo

lint: setup
	$(BIN)/ruff check src tests benchmarks

test: lint blender
	bash scripts/web.sh test
	$(BIN)/pytest -q

# Only the web parts: Vitest, server tests and the browser end-to-end tests (pytest -m web).
test-web: setup
	bash scripts/web.sh test
	$(BIN)/pytest -q tests/web

bench: setup
	for bench in benchmarks/bench_*.py; do $(BIN)/python $$bench || exit 1; done
