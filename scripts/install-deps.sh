#!/usr/bin/env bash
# Installs the Debian packages fpmshell needs to build, test and plot (README "Dependencies"),
# and those named as arguments.
# Checks each package with dpkg; as root installs the missing ones with apt-get, otherwise
# prints the exact command to run and exits 1. FPMSHELL_SKIP_DEPS=1 skips the check (for
# machines where the libraries come from elsewhere).
set -euo pipefail

PACKAGES=(
    build-essential cmake clang-format
    libeigen3-dev libyaml-cpp-dev libcli11-dev libfmt-dev
    libgtest-dev libbenchmark-dev zlib1g-dev libgmsh-dev libmetis-dev libopenmpi-dev openmpi-bin
    libmuparser-dev
    python3 python3-matplotlib python3-numpy python3-yaml python3-vtk9
)

# Packages named on the command line are needed too (make fuzz: clang and its libFuzzer).
PACKAGES+=("$@")

if [[ "${FPMSHELL_SKIP_DEPS:-0}" == "1" ]]; then
    exit 0
fi

if ! command -v dpkg >/dev/null 2>&1; then
    echo "install-deps: dpkg not found (not a Debian-based system); install the equivalents of" \
         "these packages yourself: ${PACKAGES[*]}" >&2
    exit 0
fi

missing=()
for pkg in "${PACKAGES[@]}"; do
    if ! dpkg -s "$pkg" 2>/dev/null | grep -q '^Status: install ok installed'; then
        missing+=("$pkg")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    exit 0
fi

if [[ "$(id -u)" -eq 0 ]]; then
    echo "install-deps: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    if ! { apt-get update && apt-get install -y "${missing[@]}"; }; then
        echo "install-deps: apt-get could not install ${missing[*]}; check the network and" \
             "the apt sources, then run 'make' again." >&2
        exit 1
    fi
else
    echo "install-deps: missing Debian packages: ${missing[*]}" >&2
    echo "Install them with:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
