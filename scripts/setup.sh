#!/usr/bin/env bash
# Idempotent set-up of everything fricon needs on a Debian 12 machine (as root, or with sudo):
# gfortran, OpenBLAS (the BLAS/LAPACK provider; its OpenMP build selected, see below), LAPACK,
# GSL, gnuplot-nox, and fpm from PyPI.
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=0
for cmd in gfortran gnuplot gsl-config; do
  command -v "$cmd" >/dev/null 2>&1 || missing=1
done
for pkg in libopenblas-dev libopenblas0-openmp liblapack-dev libgsl-dev gnuplot-nox gfortran; do
  dpkg -s "$pkg" >/dev/null 2>&1 || missing=1
done
# fpm comes from PyPI: a machine without Python's pip gets Debian's
pip_packages=""
if ! command -v fpm >/dev/null 2>&1 && ! python3 -m pip --version >/dev/null 2>&1; then
  pip_packages="python3 python3-pip"
  missing=1
fi
if [ "$missing" -eq 1 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends \
    gfortran libopenblas-dev libopenblas0-openmp liblapack-dev libgsl-dev gnuplot-nox \
    $pip_packages
fi

# fricon's threads are OpenMP's (a sweep's cases; every case calls BLAS on one thread), so
# Debian's OpenMP build of OpenBLAS shares their pool where the default pthread build starts a
# second one that waits (about 0.1 to 0.5 ms of every run; doc/CHOICES.md, "OpenBLAS").
# Not the serial build: it is not safe to call from two threads at once (2 to 6 of 100
# two-thread runs of input/atlas/beam.dat came out different from the serial run). Where the
# system still chooses its OpenBLAS automatically, choose the OpenMP build; a choice made by
# hand (update-alternatives in manual mode) is left alone. Undo with:
#   update-alternatives --auto libopenblas.so.0-x86_64-linux-gnu
blas_link=libopenblas.so.0-x86_64-linux-gnu
blas_openmp=/usr/lib/x86_64-linux-gnu/openblas-openmp/libopenblas.so.0
if [ -e "$blas_openmp" ] && update-alternatives --query "$blas_link" 2>/dev/null \
    | grep -q '^Status: auto'; then
  $SUDO update-alternatives --set "$blas_link" "$blas_openmp" >/dev/null
  echo "setup: OpenBLAS: the OpenMP build ($blas_openmp)"
fi

if ! command -v fpm >/dev/null 2>&1; then
  # Debian's own python3 refuses system-wide pip installs (PEP 668) unless told otherwise.
  python3 -m pip install --quiet --disable-pip-version-check fpm 2>/dev/null \
    || python3 -m pip install --quiet --disable-pip-version-check --break-system-packages fpm
fi
# a pyenv-managed Python exposes new console scripts only after a rehash
if command -v pyenv >/dev/null 2>&1; then pyenv rehash || true; fi
hash -r
if ! command -v fpm >/dev/null 2>&1; then
  echo "setup: fpm was installed but is not on PATH (add $(python3 -m site --user-base)/bin)" >&2
  exit 1
fi
echo "setup: gfortran $(gfortran -dumpversion), $(fpm --version 2>/dev/null | head -n1 | tr -s ' '), $(gnuplot --version)"
