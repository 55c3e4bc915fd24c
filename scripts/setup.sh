#!/usr/bin/env bash
# Idempotent set-up of everything fricon needs on a Debian 12 machine (as root):
# gfortran, OpenBLAS (BLAS/LAPACK provider), LAPACK, GSL, gnuplot-nox, fpm.
set -euo pipefail

need_apt=0
for cmd in gfortran gnuplot gsl-config; do
  command -v "$cmd" >/dev/null 2>&1 || need_apt=1
done
for lib in libopenblas.so liblapack.so; do
  ldconfig -p 2>/dev/null | grep -q "$lib" || need_apt=1
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

if [ "$need_apt" -eq 1 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends \
    gfortran libopenblas-dev liblapack-dev libgsl-dev gnuplot-nox
fi

if ! command -v fpm >/dev/null 2>&1; then
  python3 -m pip install --quiet --disable-pip-version-check fpm
fi
hash -r
command -v fpm >/dev/null 2>&1 || { echo "setup: fpm not on PATH after pip install" >&2; exit 1; }
echo "setup: gfortran $(gfortran -dumpversion), fpm $(fpm --version 2>/dev/null | head -n1), gnuplot $(gnuplot --version)"
