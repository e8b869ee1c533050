#!/usr/bin/env bash
# Rebuild the OpenFOAM v1912 solvers kegel uses, without tree vectorisation.
#
# Why: Debian 12's OpenFOAM v1912 binaries were compiled by GCC 12 at -O3, and GCC (11 and later)
# tree vectorisation miscompiles OpenFOAM's Tensor & Vector inner products. The flux-to-velocity
# reconstruction (fvc::reconstruct, a template instantiated inside each solver) then gives wrong
# cell velocities on any mesh not aligned with the axes; every rotating oil/air VOF case diverges
# or is wrong (../shared/notes/openfoam-v1912.md; upstream OpenFOAM added `no-tree-vectorize` to
# those operators for g++ 11). The solver applications are rebuilt from Debian's own source package
# of the same version with -fno-tree-vectorize and linked against the installed Debian libraries.
# tests/python/test_openfoam_solvers.py guards the fix (a case rotated by 30 degrees must match the
# unrotated one) and shows that the stock binary fails it.
#
# Usage: build_solvers.sh DEST_BIN_DIR [CACHE_DIR]
# Idempotent: does nothing when DEST_BIN_DIR holds a stamp for this script's recipe.
set -euo pipefail

DEST=${1:?usage: build_solvers.sh DEST_BIN_DIR [CACHE_DIR]}
CACHE=${2:-${XDG_CACHE_HOME:-$HOME/.cache}/kegel/openfoam-src}
SRC_VERSION=1912.200626-1          # Debian source version matching binary 1912.200626-1+b1
SOLVERS=(
  "applications/solvers/multiphase/interFoam interFoam"
  "applications/solvers/incompressible/pimpleFoam pimpleFoam"
  "applications/solvers/incompressible/simpleFoam simpleFoam"
)
EXTRA_FLAGS="-fno-tree-vectorize"
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
RECIPE=$(cat "${BASH_SOURCE[0]}" | sha256sum | cut -c1-16)
STAMP="$DEST/.kegel-solvers-$RECIPE"
SUDO=$([ "$(id -u)" = 0 ] || echo sudo)

if [ -f "$STAMP" ]; then
  echo "setup: OpenFOAM solvers without tree vectorisation present in $DEST"
  exit 0
fi

installed=$(dpkg-query -W -f='${Version}' openfoam 2>/dev/null || true)
case "$installed" in
  1912.200626-1*) ;;
  *) echo "build_solvers.sh: expected Debian package openfoam 1912.200626-1, found '${installed:-none}'" >&2
     exit 1 ;;
esac

mkdir -p "$CACHE" "$DEST"
ORIG="$CACHE/openfoam_1912.200626.orig.tar.bz2"
if [ ! -f "$ORIG" ]; then
  # Debian's source archive: add a deb-src entry for bookworm when none is configured.
  if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "setup: adding a deb-src entry for bookworm (/etc/apt/sources.list.d/kegel-deb-src.sources)"
    printf '%s\n' "Types: deb-src" "URIs: http://deb.debian.org/debian" "Suites: bookworm" \
      "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" \
      | $SUDO tee /etc/apt/sources.list.d/kegel-deb-src.sources >/dev/null
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q
  fi
  echo "setup: fetching the openfoam $SRC_VERSION source package (45 MB) into $CACHE"
  # apt-get checks the tarball against the signed .dsc checksums.
  (cd "$CACHE" && apt-get source --download-only "openfoam=$SRC_VERSION")
fi

WORK=$(mktemp -d "${TMPDIR:-/tmp}/kegel-ofbuild.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
echo "setup: extracting sources"
members=(src wmake etc)
for s in "${SOLVERS[@]}"; do members+=("${s% *}"); done
members+=(applications/solvers/multiphase/VoF)
tar -xjf "$ORIG" -C "$WORK" "${members[@]/#/openfoam-OpenFOAM-v1912.200626/}"
ROOT="$WORK/openfoam-OpenFOAM-v1912.200626"

# The wmake environment of debian/rules (32-bit labels, double precision, system Open MPI), with
# the Debian libraries in /usr/lib as the link target.
export WM_PROJECT=OpenFOAM WM_PROJECT_VERSION=v1912 WM_PROJECT_DIR="$ROOT" WM_DIR="$ROOT/wmake"
export WM_ARCH=linux64 WM_COMPILER=Gcc WM_COMPILER_TYPE=system WM_COMPILER_LIB_ARCH=64
export WM_COMPILE_OPTION=Opt WM_PRECISION_OPTION=DP WM_LABEL_SIZE=32 WM_LABEL_OPTION=Int32
export WM_OPTIONS=linux64GccDPInt32Opt WM_MPLIB=SYSTEMOPENMPI FOAM_MPI=openmpi-system
export FOAM_SRC="$ROOT/src" LIB_SRC="$ROOT/src" FOAM_ETC="$ROOT/etc"
export FOAM_APPBIN="$WORK/bin" FOAM_USER_APPBIN="$WORK/bin"
export FOAM_LIBBIN=/usr/lib FOAM_USER_LIBBIN=/usr/lib FOAM_EXT_LIBBIN=/usr/lib
export FOAM_EXTRA_CXXFLAGS="$EXTRA_FLAGS"
export PATH="$ROOT/wmake:$PATH"
unset MAKEFLAGS
mkdir -p "$FOAM_APPBIN"

echo "setup: building wmake tools"
(cd "$ROOT/wmake/src" && ./Allmake >"$WORK/wmake-tools.log" 2>&1) \
  || { tail -20 "$WORK/wmake-tools.log" >&2; exit 1; }
echo "setup: linking headers (lnInclude)"
wmakeLnIncludeAll "$ROOT/src" >"$WORK/lninclude.log" 2>&1 \
  || { tail -20 "$WORK/lninclude.log" >&2; exit 1; }

build_one() {
  local dir=$1 name=$2 log="$WORK/$2.log"
  if ! (cd "$ROOT/$dir" && wmake >"$log" 2>&1); then
    echo "build_solvers.sh: building $name failed; last lines of $log:" >&2
    tail -30 "$log" >&2
    return 1
  fi
  grep -q -- "$EXTRA_FLAGS" "$log" || { echo "build_solvers.sh: $name built without $EXTRA_FLAGS" >&2; return 1; }
}

pids=()
for s in "${SOLVERS[@]}"; do
  echo "setup: compiling ${s#* } with $EXTRA_FLAGS (about 40 s each, two at a time)"
  build_one ${s} &
  pids+=($!)
  if [ ${#pids[@]} -ge 2 ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done

for s in "${SOLVERS[@]}"; do
  name=${s#* }
  [ -x "$FOAM_APPBIN/$name" ] || { echo "build_solvers.sh: $name missing after build" >&2; exit 1; }
  install -m 0755 "$FOAM_APPBIN/$name" "$DEST/$name.tmp" && mv -f "$DEST/$name.tmp" "$DEST/$name"
done
rm -f "$DEST"/.kegel-solvers-*
{
  echo "source=openfoam $SRC_VERSION (Debian source package)"
  echo "flags=$EXTRA_FLAGS"
  echo "built=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
  (cd "$DEST" && sha256sum "${SOLVERS[@]##* }")
} >"$STAMP"
echo "setup: installed ${SOLVERS[*]##* } into $DEST"
