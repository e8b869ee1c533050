# kegel: `make demo` and `make test` set everything up on a fresh Debian 12 machine and run.
# `make setup` is idempotent: it installs only what is missing.
SHELL := /bin/bash
.DEFAULT_GOAL := help

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
PIP    := $(PY) -m pip
STAMP  := .stamps
SUDO   := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Debian packages: compilers and build tools, the C++ dependencies, OpenFOAM v1912 with MPI,
# and the X/GL libraries the gmsh wheel loads.
APT_PACKAGES := build-essential cmake ninja-build git python3 python3-venv python3-dev \
  libeigen3-dev libsundials-dev libfftw3-dev pkg-config libgtest-dev googletest \
  openfoam openmpi-bin libopenmpi-dev bzip2 \
  libglu1-mesa libxcursor1 libxinerama1 libxft2 libxrender1 libgl1

# Python packages needed to build kegel itself (installed before the editable install, so the
# build runs without isolation and reuses them).
BUILD_PACKAGES := "scikit-build-core>=0.10" "nanobind>=2.0"

# OpenFOAM solvers rebuilt without tree vectorisation (cfd_cases/solvers/build_solvers.sh); the
# runner finds them here (kegel.cfd_cases.foam.solver_dir).
OPENFOAM_BIN ?= $(HOME)/.local/share/kegel/openfoam-v1912/bin
export KEGEL_OPENFOAM_BIN := $(OPENFOAM_BIN)

CORE_SOURCES := $(shell find mbs_core -type f 2>/dev/null) CMakeLists.txt pyproject.toml

.PHONY: help setup apt openfoam-solvers venv install demo test test-cpp test-python bench clean

help:
	@echo "make demo   - set up (apt, venv, build) and run the 32216 Table 1 scene"
	@echo "make test   - set up and run every test (C++ ctest + pytest, OpenFOAM included)"
	@echo "make bench  - set up and run the benchmarks in benchmarks/"
	@echo "make setup  - install system packages, rebuild the OpenFOAM solvers, create .venv, install kegel"

setup: apt openfoam-solvers $(STAMP)/install

openfoam-solvers: apt
	@bash cfd_cases/solvers/build_solvers.sh "$(OPENFOAM_BIN)"

apt:
	@missing=""; for p in $(APT_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "setup: installing Debian packages:$$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -q && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	else echo "setup: Debian packages present"; fi

$(VENV)/bin/python:
	$(PYTHON) -m venv $(VENV)

$(STAMP)/venv: $(VENV)/bin/python pyproject.toml
	$(PIP) install -q --upgrade pip
	$(PIP) install -q $(BUILD_PACKAGES) "pytest>=7" "pandas>=1.5" "hypothesis>=6" "dask[distributed]>=2023.1"
	@mkdir -p $(STAMP) && touch $@

$(STAMP)/install: $(STAMP)/venv $(CORE_SOURCES)
	$(PIP) install -q --no-build-isolation -e .
	@mkdir -p $(STAMP) && touch $@

demo: setup
	$(VENV)/bin/kegel run examples/32216_table1.toml

test: setup test-cpp test-python

test-cpp: apt
	cmake -S . -B build/cpp -G Ninja -DCMAKE_BUILD_TYPE=Release -DKEGEL_BUILD_TESTS=ON -DKEGEL_BUILD_PYTHON=OFF
	cmake --build build/cpp -j 2
	ctest --test-dir build/cpp --output-on-failure

test-python: openfoam-solvers $(STAMP)/install
	$(PY) -m pytest -ra

bench: setup
	cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DKEGEL_BUILD_BENCHMARKS=ON -DKEGEL_BUILD_PYTHON=OFF
	cmake --build build/bench -j 2
	build/bench/benchmarks/cpp/bench_slice
	build/bench/benchmarks/cpp/bench_cell
	build/bench/benchmarks/cpp/bench_line
	$(PY) benchmarks/run_all.py

clean:
	rm -rf build $(STAMP) results
