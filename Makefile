# make demo: create .venv, install roughcontact, run the embedded demo study.
# make test: create/update .venv, install with test extras, lint, run the whole test suite.
# make docs: build the documentation site into build/docs (offline; every warning an error).
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
DEMO_OUT ?= demo-output

.PHONY: demo test lint docs bench clean

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

$(VENV)/.installed: pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e ".[test,docs]"
	touch $@

demo: $(VENV)/.installed
	$(VENV)/bin/roughcontact demo -o $(DEMO_OUT)

lint: $(VENV)/.installed
	$(PY) -m ruff check src tests benchmarks docs/conf.py docs/_ext docs/gallery_scripts

test: $(VENV)/.installed lint
	$(PY) -m pytest -q

docs: $(VENV)/.installed
	MPLBACKEND=Agg $(PY) -m sphinx -W --keep-going -q -b html docs build/docs

bench: $(VENV)/.installed
	for script in benchmarks/*.py; do $(PY) $$script || exit 1; done

clean:
	rm -rf $(VENV) $(DEMO_OUT) build src/*.egg-info .pytest_cache .hypothesis docs/api docs/cli.md docs/gallery
