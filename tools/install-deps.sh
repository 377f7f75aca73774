#!/usr/bin/env bash
# Installs the Debian 12 packages pdq needs, only those that are missing.
# Usage: tools/install-deps.sh [build|test|viz|fuzz]   (test adds the peers and clang with
# its libFuzzer, for the suite's short fuzz run; viz adds ParaView; fuzz: clang and
# libFuzzer alone, for fuzz/)
set -euo pipefail
need=(cmake g++ make pkg-config libopenmpi-dev openmpi-bin libcli11-dev libtomlplusplus-dev
      libfmt-dev libgtest-dev libcairo2-dev libsuitesparse-dev libopenblas0-pthread)
case "${1:-build}" in
  test) need+=(lammps clang-14 libclang-rt-14-dev) ;;
  viz) need+=(lammps paraview python3-paraview clang-14 libclang-rt-14-dev) ;;
  fuzz) need+=(clang-14 libclang-rt-14-dev) ;;
esac
missing=()
for p in "${need[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -ne 0 ]; then
  echo "pdq needs these Debian packages: ${missing[*]}" >&2
  echo "install them as root: apt-get install ${missing[*]}" >&2
  exit 1
fi
echo "installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
