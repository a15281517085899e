# rosvar: set-up and everyday jobs.
#
#   make demo        set up what rosvar needs to run, analyse the bundled example workspace
#                    (examples/) and serve the web UI on it (Ctrl-C stops; DEMO_PATHS and
#                    DEMO_PORT override)
#   make test        set up what the tests need as well, then run ruff, mypy and the whole
#                    pytest suite (the browser tests in a process of their own, away from the
#                    analyses' memory); what CI runs
#   make check       the tests' set-up, then the fast loop of everyday work: ruff, mypy and the
#                    pytest suite without the browser tests and the slow ones
#   make bench       the tests' set-up, then the benchmarks (they drive the browser too)
#   make setup       only the set-up to run rosvar (idempotent; quick when already done)
#   make test-setup  only the set-up of the tests (idempotent)
#
# The run-time set-up installs Debian's python3-venv if missing (apt-get, as root or through
# sudo), creates the virtual environment .venv and installs rosvar into it in editable mode
# (plain Python: no compiler, no build step). The tests' set-up adds Debian's roslaunch and
# chromium, rosvar's test tools (pytest, mypy, ruff, Playwright, ...: the `test` extras) and
# the ROS 2 oracle, so `make test` always tests the sources as they are.

PYTHON ?= python3
VENV   := .venv
VPY    := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
TEST_STAMP := $(VENV)/.installed-test

# --- System (Debian) packages -----------------------------------------------------------------
# One entry per package in RUNTIME_PACKAGES (rosvar itself) or TEST_PACKAGES (the tests), and
# one shell check per package in CHECK_<package>: a package is installed only when its check
# fails. To add a package, append it to one list and define its CHECK_ variable.
#   python3-roslaunch: the real roslaunch, used by the differential tests' oracle
#                      (tests/oracle/roslaunch_oracle.py runs under Debian's /usr/bin/python3).
#   python3-venv:      lets Debian's python3 create .venv (ensurepip).
#   chromium:          the headless browser of the web UI's end-to-end tests (tests/outputs/web),
#                      driven by Playwright with executable_path (Playwright's own browser
#                      builds are never downloaded).
RUNTIME_PACKAGES := python3-venv
TEST_PACKAGES := python3-roslaunch chromium
CHECK_python3-roslaunch := /usr/bin/python3 -c 'import roslaunch'
CHECK_python3-venv := $(PYTHON) -c 'import ensurepip, venv'
CHECK_chromium := /usr/bin/chromium --version

APT_ENV := env DEBIAN_FRONTEND=noninteractive
# Empty when we are root; "sudo" when we are not and sudo exists.
SUDO := $(shell if [ "$$(id -u)" != 0 ] && command -v sudo >/dev/null 2>&1; then echo sudo; fi)

.DEFAULT_GOAL := setup
.PHONY: ros2-oracle setup test-setup system-packages test-system-packages bytecode demo lint check test bench

# The ROS 2 launch oracle (the real ros2/launch, for the ROS 2 differential tests), when
# ../shared/ros2-oracle is beside the repository; its setup.sh is idempotent.
ROS2_ORACLE      := ../shared/ros2-oracle
ROS2_ORACLE_VENV := .oracle-ros2-venv

setup: system-packages $(STAMP) bytecode

test-setup: setup test-system-packages $(TEST_STAMP) ros2-oracle

# rosvar's modules byte-compiled now, as `pip install` does for a regular install: an editable
# one compiles at the first import, and where PYTHONDONTWRITEBYTECODE is set every process
# would compile them again (about 0.15 s a run). Only changed files are compiled again.
bytecode: | $(STAMP)
	@$(VPY) -m compileall -q src

ros2-oracle:
	@if [ -d $(ROS2_ORACLE) ]; then $(ROS2_ORACLE)/setup.sh $(ROS2_ORACLE_VENV); \
	else echo "No $(ROS2_ORACLE): the ROS 2 differential tests will be skipped"; fi

# $(call install-missing,PACKAGES): apt-get install those of PACKAGES whose check fails.
define install-missing
	@missing=""; \
	$(foreach p,$(1),( $(CHECK_$(p)) ) >/dev/null 2>&1 || missing="$$missing $(p)";) \
	if [ -n "$$missing" ]; then \
	  echo "Installing system packages:$$missing"; \
	  $(SUDO) $(APT_ENV) apt-get update && \
	  $(SUDO) $(APT_ENV) apt-get install -y --no-install-recommends $$missing || exit 1; \
	  failed=""; \
	  $(foreach p,$(1),( $(CHECK_$(p)) ) >/dev/null 2>&1 || failed="$$failed $(p)";) \
	  if [ -n "$$failed" ]; then echo "Still unusable after installation:$$failed" >&2; exit 1; fi; \
	fi
endef

system-packages:
	$(call install-missing,$(RUNTIME_PACKAGES))

test-system-packages:
	$(call install-missing,$(TEST_PACKAGES))

$(VPY): | system-packages
	@echo "Creating the virtual environment $(VENV)"
	$(PYTHON) -m venv $(VENV)

# Reinstalled only when the project's metadata changes (the install is editable).
$(STAMP): pyproject.toml | $(VPY)
	@echo "Installing rosvar into $(VENV) (pip)"
	$(VENV)/bin/pip install --disable-pip-version-check --progress-bar off -e .
	touch $@

$(TEST_STAMP): pyproject.toml $(STAMP)
	@echo "Installing rosvar's test tools into $(VENV) (pip)"
	$(VENV)/bin/pip install --disable-pip-version-check --progress-bar off -e '.[test]'
	touch $@

# The web UI on the example, plus the Lizi corpus system when ../shared/corpus is there.
DEMO_PATHS ?= examples $(wildcard ../shared/corpus/lizi)
DEMO_PORT  ?= 8080

demo: setup
	$(VENV)/bin/rosvar analyze examples
	$(VENV)/bin/rosvar serve $(DEMO_PATHS) --port $(DEMO_PORT)

lint: test-setup
	$(VPY) -m ruff check src tests bench tools docs/screenshot.py
	$(VPY) -m ruff format --check .
	$(VPY) -m mypy

check: lint
	$(VPY) -m pytest -q --ignore=tests/outputs/web -m "not slow"

test: lint
	$(VPY) -m pytest -q --ignore=tests/outputs/web
	$(VPY) -m pytest -q tests/outputs/web

bench: test-setup
	$(VPY) bench/run.py
