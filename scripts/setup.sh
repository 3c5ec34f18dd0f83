#!/usr/bin/env bash
# Install the Debian packages the suite needs, if any is missing.
# Usage: scripts/setup.sh   (as root, or with sudo available)
set -euo pipefail

packages=(
  libdeal.ii-dev   # deal.II 9.4 with Trilinos, PETSc, UMFPACK, MPI, gmsh
  cmake g++ make   # build
  numdiff          # deal.II's test comparisons
  openmpi-bin      # mpirun for the parallel tests and runs
  libopenblas0-serial  # optimised BLAS for MUMPS (3D runs), one thread per rank
  clang-format     # formatting check
  gnuplot-nox      # PNG plots
  python3          # study and report scripts
)

missing=()
for p in "${packages[@]}"; do
  case "$p" in \#*) continue ;; esac
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq \
    --no-install-recommends "${missing[@]}" > /dev/null
fi
echo "setup: all packages present"
