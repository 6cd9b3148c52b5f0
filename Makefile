# Every target runs exactly what CI runs. The virtual environment is made here,
# so a fresh machine needs nothing but python3.
PY      ?= python3
VENV    := .venv
BIN     := $(VENV)/bin
STAMP   := $(VENV)/.installed
SAMPLE  ?= samples/six_link_press.toml
OUT     ?= out

.PHONY: run test bench lint fonts browser clean fuzz cad-check sheets-lint bytecode

$(STAMP): pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q -e '.[test]'
	touch $(STAMP)

# The fonts: osifont, the drafting font of the sheets (ISO 3098 / GOST 2.304,
# with Cyrillic), and Liberation Serif, metric-compatible with Times New Roman,
# for the note (seed 003 §III). Installed from Debian's packages where they
# are missing; a machine without apt keeps its fallback fonts.
FONT_PACKAGES := fonts-osifont fonts-liberation2
fonts:
	@{ fc-list 2>/dev/null | grep -qi osifont && fc-list 2>/dev/null | grep -qi "liberation serif"; } || \
	  { command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ] && \
	    (apt-get install -y -q $(FONT_PACKAGES) >/dev/null 2>&1 || \
	     (apt-get update -q >/dev/null 2>&1 && apt-get install -y -q $(FONT_PACKAGES) >/dev/null 2>&1)) ; } || \
	  echo "fonts not installed ($(FONT_PACKAGES)): sheets and note use fallback fonts"

# The browser test (tests/web/test_browser.py): Debian's Chromium and its
# chromedriver, installed from Debian's packages where they are missing; a
# machine without them (or without apt) skips that one test, saying why.
BROWSER_PACKAGES := chromium chromium-driver
browser:
	@{ command -v chromium >/dev/null && command -v chromedriver >/dev/null; } || \
	  { command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ] && \
	    (apt-get install -y -q $(BROWSER_PACKAGES) >/dev/null 2>&1 || \
	     (apt-get update -q >/dev/null 2>&1 && apt-get install -y -q $(BROWSER_PACKAGES) >/dev/null 2>&1)) ; } || \
	  echo "browser not installed ($(BROWSER_PACKAGES)): the browser test skips"

# The DXF through a real CAD program: LibreCAD (Debian's package) prints both
# sheets and test drawings to PDF, read back as pixels (tests/render/
# test_dxf_librecad.py); its prints of both sheets go to docs/librecad/.
CAD_PACKAGES := librecad poppler-utils
cad-check: $(STAMP)
	@{ command -v librecad >/dev/null && command -v pdftoppm >/dev/null; } || \
	  { command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ] && \
	    (apt-get install -y -q $(CAD_PACKAGES) >/dev/null 2>&1 || \
	     (apt-get update -q >/dev/null 2>&1 && apt-get install -y -q $(CAD_PACKAGES) >/dev/null 2>&1)) ; } || \
	  echo "$(CAD_PACKAGES) not installed: the LibreCAD tests will be skipped"
	MMT_CAD_DOCS=docs/librecad $(BIN)/python -m pytest tests/render/test_dxf_librecad.py -v -rs

# The package's bytecode, written here: Python writes none where
# PYTHONDONTWRITEBYTECODE is set (as on this project's machines and CI), and
# every `mmt-plans` process, the tests' too, would compile the package again
# (about 0.5 s of each; both sheets of the default sample as SVG, whole
# process: 2.29 -> 1.74 s). Up to date, it costs a tenth of a second.
bytecode: $(STAMP)
	@$(BIN)/python -m compileall -q mmt_plans >/dev/null

run: $(STAMP) fonts bytecode
	$(BIN)/mmt-plans analyze $(SAMPLE) --json $(OUT)/results.json
	$(BIN)/mmt-plans draw $(SAMPLE) -o $(OUT)

test: $(STAMP) fonts browser bytecode
	$(BIN)/python -m pytest

# KEYS=1 adds the 55 seed-task keys on two workers (about a minute);
# SUMMARY=1 prints only the overview table
bench: $(STAMP) bytecode
	$(BIN)/python -m mmt_plans bench $(if $(KEYS),--keys) $(if $(SUMMARY),--summary)

# 20,000 seeded mutants of the samples, in-process (tests/fuzz.py): counts of
# clean errors, analysed, unexpected exceptions, non-finite outputs and slow
# cases; every 20th analysed mutant's sheets are drawn too. Exit 1 on a finding.
FUZZ_CASES ?= 20000
FUZZ_SEED  ?= 1
fuzz: $(STAMP) bytecode
	$(BIN)/python tests/fuzz.py --cases $(FUZZ_CASES) --seed $(FUZZ_SEED) --draw-every 20

# The sheet linter (mmt_plans/sheets/lint.py, run by lint_run.py) over every sample and seed task,
# variants of every sample family and generated mechanisms, both sheets in en
# and uk: a table of rule x passes / fails; each failing mechanism's file and
# findings under $(OUT)/sheets-lint/. Exit 1 while a rule fails anywhere.
LINT_GENERATED ?= 200
LINT_VARIANTS  ?= 5
LINT_JOBS      ?= 2
sheets-lint: $(STAMP) fonts bytecode
	$(BIN)/python -m mmt_plans.sheets.lint_run --generated $(LINT_GENERATED) \
	  --variants $(LINT_VARIANTS) --jobs $(LINT_JOBS) --out $(OUT)/sheets-lint

lint: $(STAMP)
	$(BIN)/ruff check mmt_plans
	$(BIN)/ruff format --check mmt_plans
	$(BIN)/mypy mmt_plans

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache
