#!/usr/bin/env bash
# Installs the Debian 12 packages flexehd needs, only those that are missing.
# Works as root or through sudo; idempotent (a second run installs nothing).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config
  libopenblas0-pthread  # optimised BLAS behind CHOLMOD: 4x faster factorizations
  libeigen3-dev libspectra-dev libsuitesparse-dev libgmsh-dev libvtk9-dev
  nlohmann-json3-dev libcli11-dev libspdlog-dev libfmt-dev libgtest-dev libyaml-cpp-dev libhdf5-dev
  libopenmpi-dev openmpi-bin  # MPI: `flexehd sweep` distributes design studies over ranks
  libfftw3-dev  # FFTW3: spectra of acoustics/ (slap-noise post-processing)
)
# Optional extras for the plotting and checking helpers in scripts/ (--with-python).
PYTHON_PACKAGES=(python3-numpy python3-matplotlib python3-vtk9)

if [[ "${1:-}" == "--with-python" ]]; then
  PACKAGES+=("${PYTHON_PACKAGES[@]}")
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
  else
    echo "install_deps: missing packages (${missing[*]}) and not root, no sudo available" >&2
    exit 1
  fi
fi

echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
