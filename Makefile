# make demo: create .venv, install roughcontact, run the embedded demo study.
# make test: create/update .venv, install with test extras, lint, run the whole test suite.
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
DEMO_OUT ?= demo-output

.PHONY: demo test lint bench clean

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip

$(VENV)/.installed: pyproject.toml | $(PY)
	$(PY) -m pip install --quiet -e ".[test]"
	touch $@

demo: $(VENV)/.installed
	$(VENV)/bin/roughcontact demo -o $(DEMO_OUT)

lint: $(VENV)/.installed
	$(PY) -m ruff check src tests benchmarks

test: $(VENV)/.installed lint
	$(PY) -m pytest -q

bench: $(VENV)/.installed
	for script in benchmarks/*.py; do $(PY) $$script || exit 1; done

clean:
	rm -rf $(VENV) $(DEMO_OUT) build src/*.egg-info .pytest_cache .hypothesis
